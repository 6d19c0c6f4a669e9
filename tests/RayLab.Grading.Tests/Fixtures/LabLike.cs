using System.Runtime.CompilerServices;

namespace RayLab.Grading.Tests.Fixtures;

// (instance members that need no instance: shaped as a lab's cameras are)
#pragma warning disable CA1822

// Classes shaped like a lab's, scanned by AssemblyUsesTests in this test assembly's own metadata. None of them runs.

/// <summary>Writes its camera itself: only Lab I's parts and the base library.</summary>
public sealed class OwnCamera
{
    public Ray GetRay(double x, double y) => new(new Double3(x, y, 0), Double3.Normalize(new Double3(0, 0, -1)));
}

/// <summary>Hands its work to RayLab's own camera.</summary>
public sealed class DelegatingCamera
{
    public Ray GetRay(int x, int y, int nx, int ny) =>
        new OrthoCamera { Position = new Double3(0, 0, 5) }.GetImagePlane(nx, ny).GetPixelRay(x, y, 0.5, 0.5);
}

/// <summary>Finds RayLab's camera by name and calls it through a helper, in a lambda.</summary>
public sealed class ReflectingCamera
{
    public object Make() => Activator.CreateInstance(Type.GetType("RayLab.Orth" + "oCamera, RayLab.Core")!)!;

    public Func<object, object?> Plane => camera => ReflectionHelper.Call(camera, "GetImagePlane", 4, 3);
}

/// <summary>A helper only <see cref="ReflectingCamera"/> reaches.</summary>
internal static class ReflectionHelper
{
    public static object? Call(object target, string name, params object[] args) => target.GetType().GetMethod(name)!.Invoke(target, args);
}

/// <summary>Reaches private members without reflection's API, and native code.</summary>
internal static class Sneaky
{
    [UnsafeAccessor(UnsafeAccessorKind.Method, Name = "ToString")]
    public static extern string Peek(object target);

    [System.Runtime.InteropServices.DllImport("libc", EntryPoint = "getpid")]
    public static extern int Pid();
}
