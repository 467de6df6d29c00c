using AcDream.Core.Physics.Tests.Motion;
using AcDream.Core.Physics.Dat.Tests.Support;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Parity;

namespace AcDream.Core.Physics.Dat.Tests;

/// <summary>
/// The synthetic humanoid of the shared ACE motion folder (shared/ace-motion/table.json, read through the JSON
/// reader) written as DAT MotionTable and Animation objects, read back and converted: the same table to the bit,
/// and every parity file gives the same report through the DAT table as through the JSON one. Compiled only when
/// the folder exists (see the test project).
/// </summary>
public class SharedMotionDatParityTests
{
    private static string Folder => SharedFolders.Find("ace-motion")!;

    private static MotionTable JsonTable() => MotionTableReader.Parse(File.ReadAllText(Path.Combine(Folder, "table.json")));

    private static readonly Lazy<(TempDats Dats, MotionTable Table)> DatTable = new(() =>
    {
        var json = JsonTable();
        var dats = new TempDats(MotionTableWriter.Objects(json));
        using var files = dats.Open();
        return (dats, DatMotionTables.Load(files, json.Id));
    });

    public static TheoryData<string> Files()
    {
        var data = new TheoryData<string>();
        if (SharedFolders.Find("ace-motion") is { } dir)
            foreach (string file in Directory.GetFiles(dir, "*.json.gz").OrderBy(f => f, StringComparer.Ordinal))
                data.Add(Path.GetFileName(file));
        return data;
    }

    [Fact]
    public void TheSharedTable_ThroughADat_IsTheJsonTable_ToTheBit()
    {
        MotionTableAssert.Same(JsonTable(), DatTable.Value.Table);
    }

    [Theory]
    [MemberData(nameof(Files))]
    public void EveryMotionFile_GivesTheSameReportThroughTheDatTable(string file)
    {
        var set = ParityReader.ReadFile(Path.Combine(Folder, file));
        Assert.NotNull(set.Motion);
        var throughJson = MotionParityCheck.Check(set.Motion!);
        var throughDat = MotionParityCheck.Check(set.Motion! with { Table = DatTable.Value.Table });
        Assert.NotSame(set.Motion!.Table, DatTable.Value.Table);
        Assert.True(throughDat.Passed, throughDat.ToString());
        Assert.True(throughDat.Frames > 0);
        Assert.Equal(throughJson.ToString(), throughDat.ToString());
        Assert.Equal(throughJson.BitIdentical, throughDat.BitIdentical);
        Assert.Equal(BitConverter.DoubleToInt64Bits(throughJson.MaxDifference), BitConverter.DoubleToInt64Bits(throughDat.MaxDifference));
    }
}
