using System.Reflection;
using System.Reflection.Emit;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Tests.Robustness;

/// <summary>
/// The library's compiled code calls no maths routine whose result may differ between architectures or CPUs:
/// the C library's transcendental functions (through <see cref="Math"/>, <see cref="MathF"/>, double.Sin and
/// the like, or System.Numerics helpers built on them) and fused multiply-adds (explicit or "estimate",
/// directly or inside a System.Numerics method), which round once where the plain expression rounds twice.
/// <see cref="PortableMath"/> and <see cref="PortableRotation"/> replace them.
/// The check reads every method body's IL, so a call added anywhere (a lambda, a local function, a
/// generic instantiation) is found.
/// </summary>
public class PlatformMathScanTests
{
    private static readonly HashSet<string> Transcendentals =
    [
        "Sin", "Cos", "Tan", "SinCos", "SinPi", "CosPi", "TanPi", "SinCosPi", "Asin", "Acos", "Atan", "Atan2", "AsinPi", "AcosPi",
        "AtanPi", "Atan2Pi", "Sinh", "Cosh", "Tanh", "Asinh", "Acosh", "Atanh", "Pow", "Exp", "Exp2", "Exp10", "ExpM1", "Exp2M1",
        "Exp10M1", "Log", "Log2", "Log10", "LogP1", "Log2P1", "Log10P1", "Cbrt", "RootN", "Hypot", "ReciprocalEstimate",
        "ReciprocalSqrtEstimate", "FusedMultiplyAdd", "MultiplyAddEstimate", "DegreesToRadians", "RadiansToDegrees",
    ];

    /// <summary>System.Numerics members built on sine and cosine.</summary>
    private static readonly HashSet<string> TrigBuilders =
    [
        "CreateFromAxisAngle", "CreateFromYawPitchRoll", "Slerp", "CreateRotationX", "CreateRotationY", "CreateRotationZ",
        "CreateRotation", "CreateSkew",
    ];

    /// <summary>Why a call is platform-dependent, or null when it is not.</summary>
    internal static string? PlatformDependence(MethodBase m)
    {
        var type = m.DeclaringType;
        if (type is null)
            return null;
        string ns = type.Namespace ?? "";
        bool maths = type == typeof(Math) || type == typeof(MathF) || type == typeof(double) || type == typeof(float)
            || type == typeof(Half) || ns == "System.Numerics" || ns.StartsWith("System.Runtime.Intrinsics", StringComparison.Ordinal);
        if (!maths)
            return null;
        if (m.Name is "FusedMultiplyAdd" or "MultiplyAddEstimate")
            return $"{type.Name}.{m.Name}: a fused multiply-add where the CPU has one (use plain products and sums)";
        if (Transcendentals.Contains(m.Name))
            return $"{type.Name}.{m.Name}: a platform maths routine (use PortableMath)";
        if (ns == "System.Numerics" && TrigBuilders.Contains(m.Name))
            return $"{type.Name}.{m.Name}: built on the platform's sine and cosine";
        if (ns.StartsWith("System.Runtime.Intrinsics.X86", StringComparison.Ordinal) && type.Name.StartsWith("Fma", StringComparison.Ordinal))
            return $"{type.Name}.{m.Name}: a fused multiply-add";
        if (ns.StartsWith("System.Runtime.Intrinsics.Arm", StringComparison.Ordinal) && m.Name.StartsWith("Fused", StringComparison.Ordinal))
            return $"{type.Name}.{m.Name}: a fused multiply-add";
        return null;
    }

    private static readonly Dictionary<short, OpCode> OpCodesByValue = typeof(OpCodes)
        .GetFields(BindingFlags.Public | BindingFlags.Static)
        .Select(f => (OpCode)f.GetValue(null)!)
        .ToDictionary(o => o.Value);

    /// <summary>Every method a body calls, loads or constructs (call, callvirt, newobj, ldftn, ldvirtftn, jmp).</summary>
    internal static IEnumerable<MethodBase> Callees(MethodBase method)
    {
        byte[]? il;
        try { il = method.GetMethodBody()?.GetILAsByteArray(); }
        catch (InvalidOperationException) { il = null; }
        if (il is null)
            yield break;
        var typeArgs = method.DeclaringType is { IsGenericType: true } t ? t.GetGenericArguments() : null;
        var methodArgs = method is MethodInfo { IsGenericMethod: true } mi ? mi.GetGenericArguments() : null;
        int i = 0;
        while (i < il.Length)
        {
            short value = il[i] == 0xFE ? (short)(0xFE00 | il[i + 1]) : il[i];
            i += il[i] == 0xFE ? 2 : 1;
            var op = OpCodesByValue[value];
            switch (op.OperandType)
            {
                case OperandType.InlineMethod:
                    yield return method.Module.ResolveMethod(BitConverter.ToInt32(il, i), typeArgs, methodArgs)!;
                    i += 4;
                    break;
                case OperandType.InlineNone: break;
                case OperandType.ShortInlineBrTarget or OperandType.ShortInlineI or OperandType.ShortInlineVar: i += 1; break;
                case OperandType.InlineVar: i += 2; break;
                case OperandType.InlineI8 or OperandType.InlineR: i += 8; break;
                case OperandType.InlineSwitch: i += 4 + 4 * BitConverter.ToInt32(il, i); break;
                default: i += 4; break;
            }
        }
    }

    private static IEnumerable<MethodBase> Bodies(Assembly assembly)
    {
        const BindingFlags all = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly;
        foreach (var type in assembly.GetTypes())
        {
            foreach (var m in type.GetMethods(all)) yield return m;
            foreach (var c in type.GetConstructors(all)) yield return c;
        }
    }

    /// <summary>
    /// Why a System.Numerics call is platform-dependent through what it calls in turn (its IL, followed
    /// within System.Numerics, System.Runtime.Intrinsics, Math and MathF): e.g. Vector3.Transform reaches
    /// MultiplyAddEstimate. Null when nothing it reaches is.
    /// </summary>
    internal static string? IndirectDependence(MethodBase root)
    {
        var seen = new HashSet<MethodBase>();
        var pending = new Stack<(MethodBase Method, int Depth)>();
        pending.Push((root, 0));
        while (pending.Count > 0)
        {
            var (m, depth) = pending.Pop();
            if (!seen.Add(m) || depth > 8)
                continue;
            if (m != root && PlatformDependence(m) is { } why)
                return $"{root.DeclaringType?.Name}.{root.Name} reaches {why}";
            string ns = m.DeclaringType?.Namespace ?? "";
            if (m != root && ns != "System.Numerics" && !ns.StartsWith("System.Runtime.Intrinsics", StringComparison.Ordinal)
                && m.DeclaringType != typeof(Math) && m.DeclaringType != typeof(MathF))
                continue;
            foreach (var callee in Callees(m))
                pending.Push((callee, depth + 1));
        }
        return null;
    }

    /// <summary>The platform-dependent calls in an assembly: "caller → reason".</summary>
    internal static List<string> PlatformCalls(Assembly assembly, Func<MethodBase, bool>? within = null)
    {
        var found = new List<string>();
        var numerics = new Dictionary<MethodBase, string?>();
        foreach (var body in Bodies(assembly))
        {
            if (within is not null && !within(body))
                continue;
            foreach (var callee in Callees(body))
            {
                string? why = PlatformDependence(callee);
                if (why is null && callee.DeclaringType?.Namespace == "System.Numerics")
                {
                    if (!numerics.TryGetValue(callee, out why))
                        numerics[callee] = why = IndirectDependence(callee);
                }
                if (why is not null)
                    found.Add($"{body.DeclaringType?.FullName}.{body.Name} → {why}");
            }
        }
        return found;
    }

    [Fact]
    public void TheLibrary_CallsNoPlatformMathsRoutine()
    {
        var found = PlatformCalls(typeof(PhysicsEngine).Assembly);
        Assert.True(found.Count == 0, "platform-dependent maths in the library:\n" + string.Join("\n", found.Distinct()));
    }

    [Fact]
    public void TheLibrary_ReallyIsScanned_PortableMathAndFrameCallsAreSeen()
    {
        // The scan sees the library's calls (so an empty result above means something): Frame's slerp calls PortableMath.
        var slerp = typeof(Frame).GetMethod("InterpolatedRotation", BindingFlags.NonPublic | BindingFlags.Static)!;
        Assert.Contains(Callees(slerp), m => m.DeclaringType == typeof(PortableMath) && m.Name == "Acos");
    }

    private static double Probe(double x) => Math.Sin(x) + MathF.Atan2((float)x, 1f) + Quaternion.CreateFromAxisAngle(Vector3.UnitZ, (float)x).W
        + double.FusedMultiplyAdd(x, x, x) + Vector3.Transform(Vector3.UnitX, Quaternion.Identity).Y;

    [Fact]
    public void TheScan_FindsPlatformCalls_WhereThereAreSome()
    {
        var found = PlatformCalls(typeof(PlatformMathScanTests).Assembly, m => m.Name == nameof(Probe));
        Assert.Contains(found, f => f.Contains("Math.Sin", StringComparison.Ordinal));
        Assert.Contains(found, f => f.Contains("MathF.Atan2", StringComparison.Ordinal));
        Assert.Contains(found, f => f.Contains("Quaternion.CreateFromAxisAngle", StringComparison.Ordinal));
        Assert.Contains(found, f => f.Contains("Double.FusedMultiplyAdd", StringComparison.Ordinal));
        Assert.Contains(found, f => f.Contains("Vector3.Transform reaches", StringComparison.Ordinal) && f.Contains("MultiplyAddEstimate", StringComparison.Ordinal));
        Assert.Equal(1.0, Probe(0.0)); // sin 0 + atan2(0, 1) + cos 0 + 0·0 + 0
    }
}
