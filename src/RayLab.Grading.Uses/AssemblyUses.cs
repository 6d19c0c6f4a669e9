using System.Reflection;
using System.Reflection.Emit;
using System.Reflection.Metadata;
using System.Reflection.Metadata.Ecma335;
using System.Reflection.PortableExecutable;

namespace RayLab.Grading;

/// <summary>
/// What a built lab assembly uses from other assemblies, read from its metadata and IL with
/// <see cref="System.Reflection.Metadata"/>: the assembly is never loaded, and none of its code runs. Every method body
/// is decoded; each call, object creation, field access or method pointer that names a member of another assembly is a
/// <see cref="ForeignUse"/>, and so is each attribute from another assembly on the lab's own types and members, each
/// base type from another assembly, each native (<c>DllImport</c>) method and each call through a function pointer.
/// The calls between the lab's own methods are kept too, so that a use in a helper class can be traced to the classes
/// whose methods reach it (<see cref="ReachedFrom"/>).
/// </summary>
public sealed class AssemblyUses
{
    private static readonly Dictionary<short, OperandType> Operands = typeof(OpCodes)
        .GetFields(BindingFlags.Public | BindingFlags.Static)
        .Select(f => f.GetValue(null))
        .OfType<OpCode>()
        .ToDictionary(o => o.Value, o => o.OperandType);

    private readonly Dictionary<string, HashSet<string>> _callers;

    private AssemblyUses(string name, IReadOnlyList<ForeignUse> uses, Dictionary<string, HashSet<string>> callers)
    {
        Name = name;
        Uses = uses;
        _callers = callers;
    }

    /// <summary>The assembly's simple name (e.g. <c>Lab</c>).</summary>
    public string Name { get; }

    /// <summary>Every use of another assembly's member, once per (lab method, member), in metadata order.</summary>
    public IReadOnlyList<ForeignUse> Uses { get; }

    /// <summary>Reads the assembly at <paramref name="path"/>.</summary>
    /// <param name="path">A .NET assembly (a .dll built from the lab).</param>
    /// <returns>Its uses.</returns>
    /// <exception cref="BadImageFormatException">The file is not a .NET assembly.</exception>
    public static AssemblyUses Read(string path)
    {
        ArgumentException.ThrowIfNullOrEmpty(path);
        using FileStream stream = File.OpenRead(path);
        using var pe = new PEReader(stream);
        if (!pe.HasMetadata)
        {
            throw new BadImageFormatException($"{path} is not a .NET assembly (it has no metadata)", path);
        }

        return Read(pe);
    }

    // Long: one pass over the metadata in its own order (the assembly's attributes, then each type's base, interfaces, attributes, fields and methods), each a few lines beside the next.
    private static AssemblyUses Read(PEReader pe)
    {
        MetadataReader md = pe.GetMetadataReader();
        var uses = new List<ForeignUse>();
        var seen = new HashSet<ForeignUse>();
        var callers = new Dictionary<string, HashSet<string>>(StringComparer.Ordinal);
        void Add(ForeignUse use)
        {
            if (seen.Add(use))
            {
                uses.Add(use);
            }
        }

        foreach (CustomAttributeHandle a in md.GetCustomAttributes(EntityHandle.AssemblyDefinition))
        {
            AddAttribute(md, a, "(assembly)", "(attributes)", Add);
        }

        foreach (TypeDefinitionHandle th in md.TypeDefinitions)
        {
            TypeDefinition type = md.GetTypeDefinition(th);
            string owner = TopLevelName(md, th);
            if (owner == "<Module>" && type.GetMethods().Count == 0)
            {
                continue;
            }

            if (!type.BaseType.IsNil && Foreign(md, type.BaseType) is { } baseType)
            {
                Add(new ForeignUse(owner, "(base type)", baseType.Assembly, baseType.Type, "", UseKind.Member) { FromBaseLibrary = baseType.Framework });
            }

            foreach (InterfaceImplementationHandle ih in type.GetInterfaceImplementations())
            {
                if (Foreign(md, md.GetInterfaceImplementation(ih).Interface) is { } iface)
                {
                    Add(new ForeignUse(owner, "(interface)", iface.Assembly, iface.Type, "", UseKind.Member) { FromBaseLibrary = iface.Framework });
                }
            }

            foreach (CustomAttributeHandle a in type.GetCustomAttributes())
            {
                AddAttribute(md, a, owner, "(attributes)", Add);
            }

            foreach (FieldDefinitionHandle fh in type.GetFields())
            {
                foreach (CustomAttributeHandle a in md.GetFieldDefinition(fh).GetCustomAttributes())
                {
                    AddAttribute(md, a, owner, md.GetString(md.GetFieldDefinition(fh).Name), Add);
                }
            }

            foreach (MethodDefinitionHandle mh in type.GetMethods())
            {
                MethodDefinition method = md.GetMethodDefinition(mh);
                string name = LabMethodName(md, th, method);
                foreach (CustomAttributeHandle a in method.GetCustomAttributes())
                {
                    AddAttribute(md, a, owner, name, Add);
                }

                if ((method.Attributes & MethodAttributes.PinvokeImpl) != 0)
                {
                    MethodImport import = method.GetImport();
                    string library = import.Module.IsNil ? "?" : md.GetString(md.GetModuleReference(import.Module).Name);
                    Add(new ForeignUse(owner, name, library, "(native)", import.Name.IsNil ? md.GetString(method.Name) : md.GetString(import.Name), UseKind.NativeMethod));
                }

                if (method.RelativeVirtualAddress == 0)
                {
                    continue;
                }

                ReadBody(md, pe.GetMethodBody(method.RelativeVirtualAddress).GetILBytes() ?? [], owner, name, Add, callers);
            }
        }

        string assembly = md.IsAssembly ? md.GetString(md.GetAssemblyDefinition().Name) : "?";
        return new AssemblyUses(assembly, uses, callers);
    }

    /// <summary>
    /// The lab's top-level types whose methods reach <paramref name="type"/>'s through the lab's own calls, directly
    /// or through other classes of the lab (<paramref name="type"/> itself excluded); a type for which
    /// <paramref name="stop"/> holds is listed, but what reaches it is not followed.
    /// </summary>
    /// <param name="type">A top-level type of the lab, by name without namespace.</param>
    /// <param name="stop">The types the search ends at (the classes of the lab's sections).</param>
    /// <returns>The types that reach it.</returns>
    public IReadOnlySet<string> ReachedFrom(string type, Func<string, bool> stop)
    {
        ArgumentNullException.ThrowIfNull(type);
        ArgumentNullException.ThrowIfNull(stop);
        var found = new HashSet<string>(StringComparer.Ordinal);
        var next = new Queue<string>([type]);
        while (next.TryDequeue(out string? t))
        {
            if (!_callers.TryGetValue(t, out HashSet<string>? from))
            {
                continue;
            }

            foreach (string caller in from)
            {
                if (caller != type && found.Add(caller) && !stop(caller))
                {
                    next.Enqueue(caller);
                }
            }
        }

        return found;
    }

    // Long: one IL decoder: a switch over the operand kinds, every opcode's operand skipped or read in one place.
    private static void ReadBody(MetadataReader md, byte[] il, string owner, string method, Action<ForeignUse> add, Dictionary<string, HashSet<string>> callers)
    {
        int i = 0;
        while (i < il.Length)
        {
            short code = il[i++];
            if (code == 0xFE)
            {
                code = unchecked((short)(0xFE00 | il[i++]));
            }

            if (!Operands.TryGetValue(code, out OperandType operand))
            {
                return; // not IL this reader knows: the rest of the body cannot be decoded safely
            }

            switch (operand)
            {
                case OperandType.InlineMethod:
                case OperandType.InlineField:
                case OperandType.InlineTok:
                    EntityHandle token = MetadataTokens.EntityHandle(BitConverter.ToInt32(il, i));
                    if (Member(md, token) is { } member)
                    {
                        add(member with { LabType = owner, LabMethod = method });
                    }
                    else if (OwnType(md, token) is { } callee && callee != owner)
                    {
                        if (!callers.TryGetValue(callee, out HashSet<string>? set))
                        {
                            callers[callee] = set = new HashSet<string>(StringComparer.Ordinal);
                        }

                        set.Add(owner);
                    }

                    i += 4;
                    break;
                case OperandType.InlineSig when code == OpCodes.Calli.Value:
                    add(new ForeignUse(owner, method, "", "(function pointer)", "calli", UseKind.FunctionPointer));
                    i += 4;
                    break;
                case OperandType.InlineSwitch:
                    int count = BitConverter.ToInt32(il, i);
                    i += 4 + (4 * count);
                    break;
                case OperandType.InlineNone:
                    break;
                case OperandType.ShortInlineBrTarget:
                case OperandType.ShortInlineI:
                case OperandType.ShortInlineVar:
                    i += 1;
                    break;
                case OperandType.InlineVar:
                    i += 2;
                    break;
                case OperandType.InlineI8:
                case OperandType.InlineR:
                    i += 8;
                    break;
                default:
                    i += 4;
                    break;
            }
        }
    }

    private static void AddAttribute(MetadataReader md, CustomAttributeHandle handle, string owner, string method, Action<ForeignUse> add)
    {
        if (Member(md, md.GetCustomAttribute(handle).Constructor) is { } ctor)
        {
            add(ctor with { LabType = owner, LabMethod = method, Kind = UseKind.Attribute });
        }
    }

    /// <summary>The foreign member a token names, or null for the lab's own.</summary>
    private static ForeignUse? Member(MetadataReader md, EntityHandle token)
    {
        switch (token.Kind)
        {
            case HandleKind.MethodSpecification:
                return Member(md, md.GetMethodSpecification((MethodSpecificationHandle)token).Method);
            case HandleKind.MemberReference:
                MemberReference reference = md.GetMemberReference((MemberReferenceHandle)token);
                if (Foreign(md, reference.Parent) is { } parent)
                {
                    return new ForeignUse("", "", parent.Assembly, parent.Type, md.GetString(reference.Name), UseKind.Member) { FromBaseLibrary = parent.Framework };
                }

                return null;
            case HandleKind.TypeReference:
                // ldtoken of another assembly's type (typeof): no capability of its own; what is done with it is a call.
                return null;
            default:
                return null;
        }
    }

    /// <summary>The top-level type of the lab that a call token lands in (its own method), or null.</summary>
    private static string? OwnType(MetadataReader md, EntityHandle token)
    {
        switch (token.Kind)
        {
            case HandleKind.MethodDefinition:
                return TopLevelName(md, md.GetMethodDefinition((MethodDefinitionHandle)token).GetDeclaringType());
            case HandleKind.FieldDefinition:
                return TopLevelName(md, md.GetFieldDefinition((FieldDefinitionHandle)token).GetDeclaringType());
            case HandleKind.MethodSpecification:
                return OwnType(md, md.GetMethodSpecification((MethodSpecificationHandle)token).Method);
            case HandleKind.MemberReference:
                EntityHandle parent = md.GetMemberReference((MemberReferenceHandle)token).Parent;
                if (parent.Kind == HandleKind.TypeSpecification && GenericDefinition(md, (TypeSpecificationHandle)parent) is { Kind: HandleKind.TypeDefinition } own)
                {
                    return TopLevelName(md, (TypeDefinitionHandle)own);
                }

                return null;
            default:
                return null;
        }
    }

    /// <summary>A type handle of another assembly as (assembly, full name), or null for the lab's own or one that cannot be named.</summary>
    private static (string Assembly, string Type, bool Framework)? Foreign(MetadataReader md, EntityHandle handle)
    {
        switch (handle.Kind)
        {
            case HandleKind.TypeReference:
                return Reference(md, (TypeReferenceHandle)handle);
            case HandleKind.TypeSpecification:
                EntityHandle generic = GenericDefinition(md, (TypeSpecificationHandle)handle);
                return generic.Kind == HandleKind.TypeReference ? Reference(md, (TypeReferenceHandle)generic)
                    : generic.IsNil ? ("?", "(type specification)", false) : null;
            default:
                return null;
        }
    }

    private static (string Assembly, string Type, bool Framework)? Reference(MetadataReader md, TypeReferenceHandle handle)
    {
        TypeReference reference = md.GetTypeReference(handle);
        string name = md.GetString(reference.Name);
        string space = md.GetString(reference.Namespace);
        EntityHandle scope = reference.ResolutionScope;
        if (scope.Kind == HandleKind.TypeReference)
        {
            (string Assembly, string Type, bool Framework)? outer = Reference(md, (TypeReferenceHandle)scope);
            return outer is { } o ? (o.Assembly, $"{o.Type}+{name}", o.Framework) : null;
        }

        string full = space.Length == 0 ? name : $"{space}.{name}";
        return scope.Kind switch
        {
            HandleKind.AssemblyReference => (md.GetString(md.GetAssemblyReference((AssemblyReferenceHandle)scope).Name), full, BaseLibrary(md, (AssemblyReferenceHandle)scope)),
            HandleKind.ModuleReference => (md.GetString(md.GetModuleReference((ModuleReferenceHandle)scope).Name), full, false),
            _ => null, // this module's own type
        };
    }

    /// <summary>The generic type a type specification instantiates (its definition or reference), or a nil handle.</summary>
    private static EntityHandle GenericDefinition(MetadataReader md, TypeSpecificationHandle handle)
    {
        BlobReader blob = md.GetBlobReader(md.GetTypeSpecification(handle).Signature);
        var header = (SignatureTypeCode)blob.ReadByte();
        if (header != SignatureTypeCode.GenericTypeInstance)
        {
            return default;
        }

        blob.ReadByte(); // class or value type
        return blob.ReadTypeHandle();
    }

    /// <summary>
    /// The public key tokens Microsoft signs .NET's shared framework with (System.Private.CoreLib, System.*, netstandard,
    /// Microsoft.*): a reference that carries one is to the base library.
    /// </summary>
    private static readonly HashSet<string> FrameworkTokens = new(StringComparer.OrdinalIgnoreCase)
    {
        "b03f5f7f11d50a3a", "cc7b13ffcd2ddd51", "7cec85d7bea7798e", "adb9793829ddae60", "31bf3856ad364e35", "b77a5c561934e089",
    };

    private static bool BaseLibrary(MetadataReader md, AssemblyReferenceHandle handle)
    {
        AssemblyReference reference = md.GetAssemblyReference(handle);
        byte[] key = md.GetBlobBytes(reference.PublicKeyOrToken);
        if (key.Length == 0)
        {
            return false;
        }

        if ((reference.Flags & AssemblyFlags.PublicKey) != 0)
        {
            // a full public key: its token is the last 8 bytes of its SHA-1, reversed (the format's own definition, not security)
#pragma warning disable CA5350
            byte[] hash = System.Security.Cryptography.SHA1.HashData(key);
#pragma warning restore CA5350
            key = [.. hash[^8..].Reverse()];
        }

        return FrameworkTokens.Contains(Convert.ToHexString(key));
    }

    private static string TopLevelName(MetadataReader md, TypeDefinitionHandle handle)
    {
        TypeDefinition type = md.GetTypeDefinition(handle);
        while (!type.GetDeclaringType().IsNil)
        {
            handle = type.GetDeclaringType();
            type = md.GetTypeDefinition(handle);
        }

        return md.GetString(type.Name);
    }

    /// <summary>
    /// The method as a student wrote it: a lambda's, a local function's, an iterator's or an async method's compiled
    /// form named after the method it is written in (<c>&lt;GetRay&gt;b__3_0</c> → <c>GetRay</c>), a property's
    /// accessor after the property (<c>get_Position</c> → <c>Position</c>), a constructor after its class.
    /// </summary>
    private static string LabMethodName(MetadataReader md, TypeDefinitionHandle typeHandle, MethodDefinition method)
    {
        string name = md.GetString(method.Name);
        if (name.StartsWith('<') && name.IndexOf('>', StringComparison.Ordinal) is > 1 and int end)
        {
            return name[1..end];
        }

        TypeDefinition type = md.GetTypeDefinition(typeHandle);
        while (md.GetString(type.Name) is { } typeName && typeName.StartsWith('<') && !type.GetDeclaringType().IsNil)
        {
            if (typeName.IndexOf('>', StringComparison.Ordinal) is > 1 and int close)
            {
                return typeName[1..close]; // an async method's or an iterator's state machine
            }

            type = md.GetTypeDefinition(type.GetDeclaringType());
        }

        return name switch
        {
            ".ctor" or ".cctor" => TopLevelName(md, typeHandle),
            _ when name.StartsWith("get_", StringComparison.Ordinal) || name.StartsWith("set_", StringComparison.Ordinal) => name[4..],
            _ => name,
        };
    }
}
