using BenchmarkDotNet.Running;

namespace AcDream.Core.Physics.Bench;

/// <summary>Entry point: runs the benchmarks selected on the command line.</summary>
public static class Program
{
    /// <summary>Runs BenchmarkDotNet's switcher over this assembly.</summary>
    public static void Main(string[] args) => BenchmarkSwitcher.FromAssembly(typeof(Program).Assembly).Run(args);
}
