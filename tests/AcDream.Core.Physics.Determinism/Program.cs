using System.Globalization;
using System.Runtime.InteropServices;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Robustness;

// Prints, one value per line, everything the determinism data records plus more fuzz frames:
//   input.<area>  case seed, hash of the generated case (so a case generated differently is told apart)
//   area.<area>   every frame of the area's cases, as the raw bits RecordedDeterminismTests compares
//   fuzz          every frame of the first 100 classic cases of DeterminismTests' run seed
//   scene.<name>  each built-in scene mover's hash over every frame
//   maths.<fn>    a hash of PortableMath's results over 20,000 inputs (the platform's hash on a '#' line:
//                 it may differ between architectures; the portable one must not)
// Lines starting with '#' describe the run and are not compared. Exit 0; a crash exits non-zero.
CultureInfo.DefaultThreadCurrentCulture = CultureInfo.InvariantCulture;
CultureInfo.CurrentCulture = CultureInfo.InvariantCulture;
var output = Console.Out;
output.WriteLine($"# acdream determinism: {RuntimeInformation.ProcessArchitecture}, {RuntimeInformation.FrameworkDescription}, {RuntimeInformation.OSDescription}");
var started = System.Diagnostics.Stopwatch.StartNew();

foreach (var area in DeterminismRecord.Areas)
{
    foreach (string line in DeterminismRecord.InputLines(area.Seed, DeterminismRecord.CasesPerArea, area.Features))
        output.WriteLine($"input.{area.Name}\t{line}");
    foreach (string line in DeterminismRecord.AreaLines(area))
        output.WriteLine($"area.{area.Name}\t{line}");
}

const int FuzzSeed = 777, FuzzCases = 100; // DeterminismTests.HashSeed and its case count
foreach (string line in DeterminismRecord.InputLines(FuzzSeed, FuzzCases, SceneFuzzer.Features.None))
    output.WriteLine($"input.fuzz\t{line}");
foreach (string line in DeterminismRecord.CaseLines(FuzzSeed, FuzzCases, SceneFuzzer.Features.None))
    output.WriteLine($"fuzz\t{line}");

foreach (string name in SceneLibrary.Names)
    foreach (string line in DeterminismRecord.SceneLines(name))
        output.WriteLine($"scene.{name}\t{line}");

// The portable maths directly, and the platform's for comparison (informational).
const int MathsInputs = 20_000;
var rng = new Random(2024);
var inputs = new (double A, double B)[MathsInputs];
for (int i = 0; i < MathsInputs; i++)
    inputs[i] = (rng.NextDouble() * 4 - 2, rng.NextDouble() * 4 - 2);
void Maths(string name, Func<double, double, double> portable, Func<double, double, double> platform, Func<double, double> scale)
{
    ulong hp = 14695981039346656037UL, hq = hp;
    int differ = 0;
    foreach (var (a, b) in inputs)
    {
        double x = scale(a), p = portable(x, b), q = platform(x, b);
        if (BitConverter.DoubleToInt64Bits(p) != BitConverter.DoubleToInt64Bits(q)) differ++;
        for (int k = 0; k < 8; k++)
        {
            hp = (hp ^ (byte)(BitConverter.DoubleToUInt64Bits(p) >> (8 * k))) * 1099511628211UL;
            hq = (hq ^ (byte)(BitConverter.DoubleToUInt64Bits(q) >> (8 * k))) * 1099511628211UL;
        }
    }
    output.WriteLine($"maths.{name}\t0x{hp:X16}");
    output.WriteLine($"# platform.{name}\t0x{hq:X16}\t{differ} of {MathsInputs} differ from the portable result");
}
Maths("sin", (x, _) => PortableMath.Sin(x), (x, _) => Math.Sin(x), a => a * 4);
Maths("cos", (x, _) => PortableMath.Cos(x), (x, _) => Math.Cos(x), a => a * 4);
Maths("acos", (x, _) => PortableMath.Acos(x), (x, _) => Math.Acos(x), a => a / 2);
Maths("atan2", (y, x) => PortableMath.Atan2(y, x), (y, x) => Math.Atan2(y, x), a => a);
Maths("pow", (x, y) => PortableMath.Pow(x, y), (x, y) => Math.Pow(x, y), a => Math.Abs(a) / 2);
Maths("sinf", (x, _) => PortableMath.Sin((float)x), (x, _) => MathF.Sin((float)x), a => a * 4);
Maths("atan2f", (y, x) => PortableMath.Atan2((float)y, (float)x), (y, x) => MathF.Atan2((float)y, (float)x), a => a);

output.WriteLine($"# done in {started.Elapsed.TotalSeconds:F1} s");
return 0;
