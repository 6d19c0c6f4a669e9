namespace RayLab.Grading;

/// <summary>What kind of use a <see cref="ForeignUse"/> is.</summary>
public enum UseKind
{
    /// <summary>A call, an object creation, a field access or a method pointer naming another assembly's member, or a base type or interface from another assembly.</summary>
    Member,

    /// <summary>An attribute from another assembly on one of the lab's types or members.</summary>
    Attribute,

    /// <summary>A method the lab declares as native code (<c>DllImport</c>, <c>LibraryImport</c>'s stub).</summary>
    NativeMethod,

    /// <summary>A call through a function pointer (<c>calli</c>).</summary>
    FunctionPointer,
}

/// <summary>One member of another assembly that one method of the lab uses.</summary>
/// <param name="LabType">The lab's top-level class it is used in (a lambda's or a nested class's outermost class), e.g. <c>LabOrthoCamera</c>.</param>
/// <param name="LabMethod">The method it is used in, as written (<c>GetRay</c>; a property by its name; a constructor by its class's).</param>
/// <param name="Assembly">The assembly the member comes from (e.g. <c>RayLab.Core</c>, <c>System.Runtime</c>); the native library for a native method.</param>
/// <param name="Type">The member's type, with its namespace (<c>RayLab.OrthoCamera</c>; a nested type as <c>Outer+Inner</c>).</param>
/// <param name="Member">The member's metadata name (<c>GetImagePlane</c>, <c>.ctor</c>, <c>get_Position</c>); empty for a base type or an interface.</param>
/// <param name="Kind">What kind of use it is.</param>
public sealed record ForeignUse(string LabType, string LabMethod, string Assembly, string Type, string Member, UseKind Kind)
{
    /// <summary>
    /// Whether <see cref="Assembly"/> is one of .NET's own (the base library): a reference that carries one of the
    /// public key tokens Microsoft signs the shared framework with.
    /// </summary>
    public bool FromBaseLibrary { get; init; }

    /// <summary>The member as a student reads it: <c>OrthoCamera.GetImagePlane</c>, <c>new OrthoCamera</c>, <c>OrthoCamera.Position</c>.</summary>
    public string Display
    {
        get
        {
            string type = Type[(Type.LastIndexOf('.') + 1)..].Replace('+', '.');
            int tick = type.IndexOf('`', StringComparison.Ordinal);
            type = tick >= 0 ? type[..tick] : type;
            return Kind switch
            {
                UseKind.NativeMethod => $"{Member} ({Assembly})",
                UseKind.FunctionPointer => "calli",
                _ => Member switch
                {
                    "" => type,
                    ".ctor" when Kind == UseKind.Attribute => $"[{type}]",
                    ".ctor" => $"new {type}",
                    _ when Member.StartsWith("get_", StringComparison.Ordinal) || Member.StartsWith("set_", StringComparison.Ordinal) => $"{type}.{Member[4..]}",
                    _ => $"{type}.{Member}",
                },
            };
        }
    }
}
