using System;
using System.Collections.Generic;
using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.World;

/// <summary>
/// All cells of the world by id, and the retail cell-list search (find_cell_list): which cells a set of
/// spheres touches, and which of them holds the first sphere's centre.
/// Not modelled: retail's visibility filter (stab lists) that drops indoor cells not visible from the
/// current one; the portal walk below reaches only connected cells anyway.
/// </summary>
public sealed class CellGraph
{
    private readonly Dictionary<uint, Cell> _cells = new();

    // The outdoor cells again, by array: the cell search and the per-frame checks look land cells up
    // several times per transition, and array reads are cheaper than a hash lookup. Filled when a
    // landblock is added, emptied when it is removed.
    private readonly CellTable<LandCell> _land = new();
    // The env cells by id, for Get (array reads rather than the hash of every cell above).
    private readonly CellTable<EnvCell> _env = new();

    // The env cells of each landblock, so a landblock is removed without a search of every cell. A
    // landblock's list is kept, empty, when it is removed (loading it again allocates no list).
    private readonly Dictionary<uint, List<EnvCell>> _envByBlock = new();

    /// <summary>
    /// Changes whenever cells are removed: work an engine remembers between calls that assumed its cells
    /// exist (the refusal memo) is forgotten.
    /// </summary>
    internal int RemovalCount { get; private set; }

    /// <summary>
    /// Adds a land block's 64 outdoor cells built from its terrain. All or nothing: a landblock already in
    /// the world or a cell that cannot be built throws before any cell is added.
    /// Single writer: add cells from one thread while no query runs.
    /// </summary>
    public void AddLandblock(Terrain terrain)
    {
        ArgumentNullException.ThrowIfNull(terrain);
        for (uint i = 1; i <= 64; i++)
        {
            uint id = (terrain.Landblock << 16) | i;
            if (_cells.ContainsKey(id))
                throw new ArgumentException($"landblock 0x{terrain.Landblock:X4}: cell 0x{id:X8} is already in the world.", nameof(terrain));
        }
        var built = new LandCell[64];
        for (uint i = 1; i <= 64; i++)
            built[i - 1] = new LandCell((terrain.Landblock << 16) | i, terrain);
        foreach (var land in built)
        {
            _cells.Add(land.Id, land);
            _land.Set(land.Id, land);
        }
    }

    /// <summary>
    /// Adds an env cell whose portals lead outside or to cells already in the world. Cells that lead to
    /// each other are added together with <see cref="AddEnvCells"/>.
    /// </summary>
    public void AddEnvCell(EnvCell cell)
    {
        ArgumentNullException.ThrowIfNull(cell);
        AddEnvCells([cell]);
    }

    /// <summary>
    /// Adds env cells together, all or none: ids new to the world and to each other, and every portal
    /// leading outside, to one of these cells or to a cell already in the world (a portal to a missing cell
    /// is refused, naming it, as the scene loader refuses it).
    /// </summary>
    public void AddEnvCells(IReadOnlyList<EnvCell> cells)
    {
        ArgumentNullException.ThrowIfNull(cells);
        for (int i = 0; i < cells.Count; i++)
        {
            var cell = cells[i] ?? throw new ArgumentNullException(nameof(cells), $"cells[{i}]: is null.");
            if (_cells.ContainsKey(cell.Id))
                throw new ArgumentException($"cell 0x{cell.Id:X8}: is already in the world.", nameof(cells));
            for (int k = 0; k < i; k++)
                if (cells[k].Id == cell.Id)
                    throw new ArgumentException($"cell 0x{cell.Id:X8}: is given twice (cells[{k}] and cells[{i}]).", nameof(cells));
        }
        foreach (var cell in cells)
            for (int p = 0; p < cell.Portals.Length; p++)
            {
                uint other = cell.Portals[p].OtherCellId;
                if (!cell.Portals[p].LeadsOutside && !_cells.ContainsKey(other) && !Given(cells, other))
                    throw new ArgumentException($"cell 0x{cell.Id:X8}.portals[{p}].otherCell: cell 0x{other:X8} is neither in the world nor added with it.", nameof(cells));
            }
        foreach (var cell in cells)
        {
            _cells.Add(cell.Id, cell);
            _env.Set(cell.Id, cell);
            uint block = cell.Id >> 16;
            if (!_envByBlock.TryGetValue(block, out var list))
                _envByBlock.Add(block, list = new List<EnvCell>());
            list.Add(cell);
        }
    }

    private static bool Given(IReadOnlyList<EnvCell> cells, uint id)
    {
        foreach (var cell in cells)
            if (cell.Id == id)
                return true;
        return false;
    }

    /// <summary>True when the landblock has land cells or env cells in the world.</summary>
    public bool HasLandblock(uint landblock) =>
        landblock <= 0xFFFF && (_land.Get((landblock << 16) | 1) is not null || _envByBlock.TryGetValue(landblock, out var env) && env.Count > 0);

    /// <summary>
    /// Takes a landblock's cells out of the graph: its 64 land cells (with the buildings standing in them)
    /// and its env cells. Only through <see cref="PhysicsWorld.UnloadLandblock"/>, which first takes the
    /// objects' rows out of those cells. Allocates nothing.
    /// </summary>
    internal void RemoveLandblock(uint landblock)
    {
        for (uint i = 1; i <= 64; i++)
        {
            uint id = (landblock << 16) | i;
            if (_cells.Remove(id))
                _land.Remove(id);
        }
        if (_envByBlock.TryGetValue(landblock, out var env))
        {
            foreach (var cell in env)
            {
                _cells.Remove(cell.Id);
                _env.Remove(cell.Id);
            }
            env.Clear();
        }
        RemovalCount++;
    }

    /// <summary>A landblock's env cells (empty when it has none), in the order they were added.</summary>
    internal ReadOnlySpan<EnvCell> EnvCellsOf(uint landblock) =>
        _envByBlock.TryGetValue(landblock, out var env) ? System.Runtime.InteropServices.CollectionsMarshal.AsSpan(env) : default;

    /// <summary>Places a building in the outdoor cell at its position; its entrance cells must exist.</summary>
    public void AddBuilding(Building building)
    {
        ArgumentNullException.ThrowIfNull(building);
        if (Get(building.Position.CellId) is not LandCell land)
            throw new ArgumentException($"building.position.cell: 0x{building.Position.CellId:X8} is not a known outdoor cell.", nameof(building));
        foreach (uint id in building.EntranceCells)
            if (Get(id) is not EnvCell)
                throw new ArgumentException($"building.entranceCells: 0x{id:X8} is not a known env cell.", nameof(building));
        if (land.Building is not null)
            throw new ArgumentException($"building: cell 0x{land.Id:X8} already has a building.", nameof(building));
        land.Building = building;
    }

    /// <summary>The cell with this id, or null.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Cell? Get(uint cellId) => (cellId & 0xFFFF) - 1 < 64 ? _land.Get(cellId) : GetIndoor(cellId);

    // Apart so that Get inlines: the land path is array reads.
    private Cell? GetIndoor(uint cellId) => _env.Get(cellId);

    /// <summary>The cell with this id; throws naming the id when unknown.</summary>
    internal Cell GetRequired(uint cellId, string field) =>
        Get(cellId) ?? throw new ArgumentException($"{field}: unknown cell 0x{cellId:X8}.", field);

    /// <summary>Every cell id, for diagnostics and validation.</summary>
    public IEnumerable<uint> CellIds => _cells.Keys;

    /// <summary>
    /// Retail find_cell_list: fills <paramref name="cells"/> with the cells the spheres (landblock space of
    /// <paramref name="position"/>'s cell) touch. When <paramref name="findContaining"/> is set, returns the
    /// cell holding sphere 0's centre, preferring an indoor cell; otherwise returns null.
    /// <paramref name="hitsInteriorCell"/> tells whether an indoor cell is listed or holds the centre (retail
    /// sets the path's hits_interior_cell there).
    /// </summary>
    internal Cell? FindCellList(in Position position, ReadOnlySpan<Sphere> spheres, CellArray cells, bool findContaining, out bool hitsInteriorCell)
    {
        hitsInteriorCell = false;
        cells.Clear();
        uint startId = position.CellId;
        Cell? start;
        // Retail adds the outside cells again for every land cell in the list (and for each indoor cell with
        // a portal to the outside near a sphere); they depend only on the spheres, so every call after the
        // first adds nothing. Remember that they are in.
        bool outsideAdded = false;
        if (!LandDefs.IsLandCell(startId))
        {
            start = Get(startId);
            hitsInteriorCell = true;
            if (start is not null) cells.Add(start);
        }
        else
        {
            var startLand = _land.Get(startId);
            if (startLand is { Building: null } && (Shortcuts & Shortcuts.LandCellAlone) != 0 && AloneInSquare(startLand, spheres))
            {
                // The usual outdoor case: the list is the start cell alone, and it holds sphere 0's centre when
                // the full search's test below says so (the same test, same bits).
                cells.Add(startLand);
                return findContaining && startLand.ContainsPoint(spheres[0].Center - LandDefs.BlockOffset(startId, startLand.Id)) ? startLand : null;
            }
            start = startLand;
            AddOutsideCells(startId, startLand, spheres, cells);
            outsideAdded = true;
        }
        if (start is null || spheres.Length == 0)
            return null;

        // One pass: the transit step of each cell (the list grows as it goes), and, for land cells, whether
        // they hold sphere 0's centre. The holder is the first indoor cell in the list that holds the centre,
        // else the last land cell that does; indoor cells are tested after the list is complete.
        var centre = spheres[0].Center;
        LandCell? landHolder = null;
        bool anyIndoor = false;
        for (int i = 0; i < cells.Count; i++)
        {
            var cell = cells[i];
            if (cell is LandCell land)
            {
                if (findContaining && land.ContainsPoint(centre - LandDefs.BlockOffset(startId, land.Id)))
                    landHolder = land;
                // Once the outside cells are in, a land cell without a building adds nothing.
                if (outsideAdded && land.Building is null)
                    continue;
            }
            else
            {
                anyIndoor = true;
            }
            AddTransitCells(cell, position, spheres, cells, ref hitsInteriorCell, ref outsideAdded);
        }
        if (!findContaining)
            return null;
        if (anyIndoor)
            for (int i = 0; i < cells.Count; i++)
                if (cells[i] is EnvCell env && ContainsCentre(env, centre, startId))
                {
                    hitsInteriorCell = true;
                    return env;
                }
        return landHolder;
    }

    /// <summary>
    /// The non-retail shortcuts this graph's cell search takes (only <see cref="Shortcuts.LandCellAlone"/> applies):
    /// the default at construction (<see cref="ShortcutSettings.Default"/>).
    /// </summary>
    internal Shortcuts Shortcuts { get; set; } = ShortcutSettings.Default;

    // The least distance from the square's edges AloneInSquare accepts (1 mm): far more than the rounding of
    // AddOutsideCells' division, so its floor lands in the cell (see below).
    private const float SquareRim = 1e-3f;

    /// <summary>
    /// Shortcut <see cref="Shortcuts.LandCellAlone"/> (not retail). Skips: the outdoor cell search (add_all_outside_cells
    /// and the transit pass) for spheres well inside a cell without a building. Same result: the search would list
    /// that cell alone (below). Proof: CellSearchShortcutTests, and the suite with shortcuts off.
    /// True when <see cref="AddOutsideCells"/> would add <paramref name="land"/> alone (retail runs
    /// the search): at least one sphere, each in the cell's square (the spheres are in the landblock space of
    /// the land cell, which is the search's start cell) at least its radius (and 1 mm) from every edge. Then a
    /// search from this cell, if it has no building, lists this cell alone, holds the centre where its
    /// <see cref="LandCell.ContainsPoint"/> does and leaves its interior-cell answer false.
    /// </summary>
    /// <remarks>
    /// Why exact, per sphere (x; y is the same), with w the square's west edge (24 × the cell column, exact):
    /// d = x − w is computed in float. Rounding is monotone, so d in [r, 24 − r] with r ≥ 1 mm means the true
    /// x − w lies in (0, 24); there x − w is exact (w is 0, or w ≤ x ≤ 2w: Sterbenz). The true x / 24 is
    /// then at least 4e-5 from the integers around the cell column (below 8), far more than the half ulp
    /// (2.4e-7) by which AddOutsideCells' division can round, so its floor is the column, its global cell
    /// coordinates are this cell's, and its px = x − floor × 24 is exact and equals d. Its neighbour test
    /// (px &gt; 24 − r, px &lt; r, with 24 − r rounded as here) then adds nothing. The centre test is the one
    /// FindCellList's loop runs on the cell. A NaN or infinite coordinate or radius fails a comparison here.
    /// </remarks>
    internal static bool AloneInSquare(LandCell land, ReadOnlySpan<Sphere> spheres)
    {
        if (spheres.Length == 0)
            return false;
        var corner = land.SouthWest;
        foreach (ref readonly var sphere in spheres)
        {
            float r = sphere.Radius, far = PhysicsConstants.LandCellLength - r;
            float dx = sphere.Center.X - corner.X, dy = sphere.Center.Y - corner.Y;
            if (!(r >= SquareRim && dx >= r && dx <= far && dy >= r && dy <= far))
                return false;
        }
        return true;
    }

    // Apart so that the land path of FindCellList stays small (no rotation matrix in its frame).
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static bool ContainsCentre(EnvCell env, Vector3 centre, uint startId) =>
        env.ContainsPoint(centre - LandDefs.BlockOffset(startId, env.Id));

    private void AddTransitCells(Cell cell, in Position position, ReadOnlySpan<Sphere> spheres, CellArray cells, ref bool hitsInteriorCell, ref bool outsideAdded)
    {
        if (cell is LandCell land)
        {
            if (!outsideAdded)
            {
                AddOutsideCells(position.CellId, null, spheres, cells);
                outsideAdded = true;
            }
            if (land.Building is { } building)
                foreach (uint id in building.EntranceCells)
                    if (Get(id) is EnvCell entrance)
                        AddIfSphereInside(entrance, position, spheres, cells, ref hitsInteriorCell);
            return;
        }
        if (cell is not EnvCell env)
            return;
        bool checkOutside = false;
        foreach (var portal in env.Portals)
        {
            var plane = portal.Polygon.Plane;
            if (portal.LeadsOutside)
            {
                foreach (var sphere in spheres)
                {
                    var local = env.ToLocal(sphere.Center - LandDefs.BlockOffset(position.CellId, env.Id));
                    float dist = VectorMath.Distance(plane, local);
                    float reach = sphere.Radius + PhysicsConstants.Epsilon;
                    if (dist > -reach && dist < reach) { checkOutside = true; break; }
                }
                continue;
            }
            if (Get(portal.OtherCellId) is EnvCell other)
                AddIfSphereInside(other, position, spheres, cells, ref hitsInteriorCell);
        }
        if (checkOutside && !outsideAdded)
        {
            AddOutsideCells(position.CellId, null, spheres, cells);
            outsideAdded = true;
        }
    }

    private static void AddIfSphereInside(EnvCell env, in Position position, ReadOnlySpan<Sphere> spheres, CellArray cells, ref bool hitsInteriorCell)
    {
        var offset = LandDefs.BlockOffset(position.CellId, env.Id);
        foreach (var sphere in spheres)
        {
            if (env.IntersectsSphere(new Sphere(sphere.Center - offset, sphere.Radius)) == BoundingType.Outside)
                continue;
            hitsInteriorCell = true;
            cells.Add(env);
            return;
        }
    }

    /// <summary>
    /// Retail add_all_outside_cells: the outdoor cell under each sphere centre plus the neighbours the
    /// sphere reaches across a cell border (check_add_cell_boundary), across landblocks too.
    /// </summary>
    /// <remarks>
    /// <paramref name="startLand"/>, when given, is the land cell <paramref name="startId"/> names: a sphere
    /// over it (the usual case) takes it instead of looking it up again.
    /// </remarks>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void AddOutsideCells(uint startId, LandCell? startLand, ReadOnlySpan<Sphere> spheres, CellArray cells)
    {
        uint block = startId >> 16;
        int blockX = (int)(block >> 8) * 8, blockY = (int)(block & 0xFF) * 8;
        // The start cell's global cell coordinates (index − 1 = x * 8 + y), when it is a loaded land cell.
        int startX = -1, startY = -1;
        if (startLand is not null)
        {
            uint index = (startId & 0xFFFF) - 1;
            startX = blockX + (int)(index >> 3);
            startY = blockY + (int)(index & 7);
        }
        for (int i = 0; i < spheres.Length; i++)
        {
            // A sphere over the one before it (the same X, Y and radius, to the bit) adds the same cells again,
            // which are all in already: the player's two stacked spheres.
            if (i > 0 && SameColumn(spheres[i], spheres[i - 1]))
                continue;
            float x = spheres[i].Center.X, y = spheres[i].Center.Y, radius = spheres[i].Radius;
            float fx = MathF.Floor(x / PhysicsConstants.LandCellLength);
            float fy = MathF.Floor(y / PhysicsConstants.LandCellLength);
            if (!float.IsFinite(fx) || !float.IsFinite(fy))
                continue;
            int gx = blockX + (int)fx, gy = blockY + (int)fy;
            float px = x - fx * PhysicsConstants.LandCellLength;
            float py = y - fy * PhysicsConstants.LandCellLength;
            float min = radius, max = PhysicsConstants.LandCellLength - radius;
            var under = gx == startX && gy == startY ? startLand : _land.GetLandAtGlobal(gx, gy);
            if (under is not null)
                cells.Add(under);
            if (px > max || px < min || py > max || py < min)
                AddNeighbours(cells, gx, gy, px, py, min, max);
        }
    }

    /// <summary>The cells beside (gx, gy) that a sphere at (px, py) in it reaches (check_add_cell_boundary), in retail's order.</summary>
    private void AddNeighbours(CellArray cells, int gx, int gy, float px, float py, float min, float max)
    {
        if (px > max)
        {
            AddOutsideCell(cells, gx + 1, gy);
            if (py > max) AddOutsideCell(cells, gx + 1, gy + 1);
            if (py < min) AddOutsideCell(cells, gx + 1, gy - 1);
        }
        if (px < min)
        {
            AddOutsideCell(cells, gx - 1, gy);
            if (py > max) AddOutsideCell(cells, gx - 1, gy + 1);
            if (py < min) AddOutsideCell(cells, gx - 1, gy - 1);
        }
        if (py > max) AddOutsideCell(cells, gx, gy + 1);
        if (py < min) AddOutsideCell(cells, gx, gy - 1);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool SameColumn(in Sphere a, in Sphere b) =>
        BitConverter.SingleToInt32Bits(a.Center.X) == BitConverter.SingleToInt32Bits(b.Center.X)
        && BitConverter.SingleToInt32Bits(a.Center.Y) == BitConverter.SingleToInt32Bits(b.Center.Y)
        && BitConverter.SingleToInt32Bits(a.Radius) == BitConverter.SingleToInt32Bits(b.Radius);

    private void AddOutsideCell(CellArray cells, int gx, int gy)
    {
        if (_land.GetLandAtGlobal(gx, gy) is { } cell)
            cells.Add(cell);
    }
}
