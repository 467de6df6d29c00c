using BenchmarkDotNet.Running;

namespace AcDream.Core.Physics.Bench;

/// <summary>
/// Entry point: <c>door</c> runs the door job, <c>body</c> the body-step job, <c>motion</c> the motion-step job, <c>queries</c> times the world
/// queries, <c>compile</c> the BSP compiler's cost job, <c>registry</c> the registry's removal and move
/// costs, <c>realcells</c> the real-cells job, <c>components</c> what each part of a transition costs, <c>trace</c>
/// prints one door approach, <c>server</c> the server tick job, <c>crowd</c> the crowd job (creatures piling onto one player), <c>dat</c> loading landblocks from DAT files, <c>chart</c> redraws the door job's speed/accuracy chart from its door.csv; anything
/// else goes to BenchmarkDotNet's switcher.
/// </summary>
public static class Program
{
    /// <summary>Runs the job named first on the command line, or the benchmarks selected by the rest.</summary>
    public static int Main(string[] args)
    {
        string[] rest = args.Skip(1).ToArray();
        switch (args.FirstOrDefault())
        {
            case "door": return DoorJob.Run(rest);
            case "body": return BodyJob.Run(rest);
            case "motion": return MotionJob.Run(rest);
            case "queries": return Queries.QueryJob.Run(rest);
            case "compile": return Compile.CompileJob.Run(rest);
            case "registry": return Registry.RegistryJob.Run();
            case "realcells": return RealCells.RealCellsJob.Run(rest);
            case "trace": return DoorTrace.Run(rest);
            case "components": return Components.ComponentJob.Run(rest);
            case "chart": return Reporting.ChartJob.Run(rest);
            case "server": return Server.ServerJob.Run(rest);
            case "crowd": return Timing.CrowdRun.Run(rest);
            case "dat": return Dat.DatJob.Run(rest);
            default:
                BenchmarkSwitcher.FromAssembly(typeof(Program).Assembly).Run(args);
                return 0;
        }
    }
}
