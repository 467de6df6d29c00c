using System;
using System.Linq;
using BenchmarkDotNet.Running;

namespace AcDream.Core.Physics.Bench;

/// <summary>Entry point: <c>door</c> runs the door job, <c>body</c> the body-step job, <c>queries</c> times the world queries, <c>compile</c> the BSP compiler's cost job; anything else goes to BenchmarkDotNet's switcher.</summary>
public static class Program
{
    /// <summary>Runs the door job or the benchmarks selected on the command line.</summary>
    public static int Main(string[] args)
    {
        if (args.Length > 0 && args[0] == "door")
            return DoorJob.Run(args.Skip(1).ToArray());
        if (args.Length > 0 && args[0] == "body")
            return BodyJob.Run(args.Skip(1).ToArray());
        if (args.Length > 0 && args[0] == "queries")
            return Queries.QueryJob.Run(args.Skip(1).ToArray());
        if (args.Length > 0 && args[0] == "compile")
            return Compile.CompileJob.Run(args.Skip(1).ToArray());
        if (args.Length > 0 && args[0] == "trace")
            return DoorTrace.Run(args.Skip(1).ToArray());
        BenchmarkSwitcher.FromAssembly(typeof(Program).Assembly).Run(args);
        return 0;
    }
}
