using System.IO;
using System.Reflection;
using System.Text.RegularExpressions;

namespace AcDream.Core.Physics.Tests.Layers;

/// <summary>
/// The layers below the transition stand alone: Geometry, Bsp, Shapes and World answer geometric questions
/// with plain values, and the transition (Transitions/, its responses in Transitions/Responses/) decides what
/// to do with the answers. So no source file of those folders names <c>Transition</c>, <c>SpherePath</c> or
/// <c>CollisionInfo</c> (code, comments or crefs) or imports the Transitions namespace, and no type of their
/// namespaces has a field, property, parameter, return value, local, base or interface of a type from it.
/// The sources are embedded into this assembly at build time (see the project file).
/// </summary>
public class LayerIndependenceTests
{
    public static TheoryData<string> Layers => new() { "Geometry", "Bsp", "Shapes", "World" };

    private const string TransitionsNamespace = "AcDream.Core.Physics.Transitions";

    private static readonly Regex TransitionNames =
        new(@"\b(Transition|SpherePath|CollisionInfo)\b|\bAcDream\.Core\.Physics\.Transitions\b", RegexOptions.Compiled);

    [Theory]
    [MemberData(nameof(Layers))]
    public void Sources_NeverNameTheTransition(string layer)
    {
        var assembly = Assembly.GetExecutingAssembly();
        var files = assembly.GetManifestResourceNames().Where(n => n.StartsWith($"Layer/{layer}/", StringComparison.Ordinal)).ToList();
        Assert.True(files.Count > 0, $"no source of {layer}/ is embedded: the project file's Layer items miss it");

        var offenders = new List<string>();
        foreach (string file in files)
        {
            using var stream = assembly.GetManifestResourceStream(file)!;
            using var reader = new StreamReader(stream);
            int lineNumber = 0;
            while (reader.ReadLine() is { } line)
            {
                lineNumber++;
                if (TransitionNames.IsMatch(line))
                    offenders.Add($"{file["Layer/".Length..]}:{lineNumber}: {line.Trim()}");
            }
        }
        Assert.True(offenders.Count == 0,
            $"{layer}/ names the transition (its responses belong in Transitions/Responses):\n" + string.Join("\n", offenders));
    }

    [Theory]
    [MemberData(nameof(Layers))]
    public void Types_UseNoTransitionType(string layer)
    {
        string ns = "AcDream.Core.Physics." + layer;
        var types = typeof(AcDream.Core.Physics.World.Cell).Assembly.GetTypes()
            .Where(t => t.Namespace == ns || (t.Namespace?.StartsWith(ns + ".", StringComparison.Ordinal) ?? false))
            .ToList();
        Assert.True(types.Count > 0, $"namespace {ns} has no type");

        const BindingFlags all = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly;
        var offenders = new List<string>();
        void Check(Type? used, Type owner, string where)
        {
            if (used is not null && FromTransitions(used))
                offenders.Add($"{owner.FullName}.{where}: {used.FullName}");
        }
        foreach (var type in types)
        {
            Check(type.BaseType, type, "base");
            foreach (var face in type.GetInterfaces())
                Check(face, type, "interface");
            foreach (var field in type.GetFields(all))
                Check(field.FieldType, type, field.Name);
            foreach (var property in type.GetProperties(all))
                Check(property.PropertyType, type, property.Name);
            foreach (var method in type.GetMethods(all).Cast<MethodBase>().Concat(type.GetConstructors(all)))
            {
                if (method is MethodInfo info)
                    Check(info.ReturnType, type, $"{method.Name} (return)");
                foreach (var parameter in method.GetParameters())
                    Check(parameter.ParameterType, type, $"{method.Name}({parameter.Name})");
                foreach (var local in method.GetMethodBody()?.LocalVariables ?? [])
                    Check(local.LocalType, type, $"{method.Name} (local {local.LocalIndex})");
            }
        }
        Assert.True(offenders.Count == 0,
            $"{ns} uses the transition's types (its responses belong in Transitions.Responses):\n" + string.Join("\n", offenders.Distinct()));
    }

    // A type of the Transitions namespace (or below), also as an array, reference, pointer or generic argument.
    private static bool FromTransitions(Type type)
    {
        if (type.HasElementType)
            return FromTransitions(type.GetElementType()!);
        if (type.IsGenericType && !type.IsGenericTypeDefinition && type.GetGenericArguments().Any(FromTransitions))
            return true;
        string? ns = type.Namespace;
        return ns is not null && (ns == TransitionsNamespace || ns.StartsWith(TransitionsNamespace + ".", StringComparison.Ordinal));
    }
}
