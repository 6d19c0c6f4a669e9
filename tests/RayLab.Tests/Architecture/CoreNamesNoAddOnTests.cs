using System.Reflection.Metadata;
using System.Reflection.Metadata.Ecma335;
using System.Reflection.PortableExecutable;

namespace RayLab.Tests.Architecture;

/// <summary>
/// The core does not reach up to an add-on by name: its assembly references no add-on and holds no string naming one
/// (the string an <c>Assembly.Load</c> or a message would need). Add-ons register what they add through the core's
/// public API (<see cref="ImageFormats.Register"/>). The friend grants in the core's project file
/// (<c>InternalsVisibleTo</c>) are attributes, not strings the code uses, and are not what this reads.
/// </summary>
public sealed class CoreNamesNoAddOnTests
{
    private static readonly string[] AddOns = ["RayLab.Reports", "RayLab.ImageSharp", "RayLab.Gpu", "ILGPU"];

    private static (string[] References, string[] Strings) ReadCore()
    {
        using var pe = new PEReader(File.OpenRead(typeof(Scene).Assembly.Location));
        MetadataReader reader = pe.GetMetadataReader();
        string[] references = [.. reader.AssemblyReferences.Select(h => reader.GetString(reader.GetAssemblyReference(h).Name))];
        var strings = new List<string>();
        for (UserStringHandle h = MetadataTokens.UserStringHandle(1); !h.IsNil; h = reader.GetNextHandle(h))
        {
            strings.Add(reader.GetUserString(h));
        }

        return (references, [.. strings]);
    }

    [Fact]
    public void The_core_assembly_references_no_add_on_and_no_string_in_its_code_names_one()
    {
        (string[] references, string[] strings) = ReadCore();

        Assert.True(strings.Length > 100, $"read only {strings.Length} strings from the core: the reader is wrong, not the core");
        Assert.Contains(strings, s => s.Contains("does not exist", StringComparison.Ordinal)); // a message the core has
        foreach (string addOn in AddOns)
        {
            Assert.DoesNotContain(references, r => r.StartsWith(addOn, StringComparison.Ordinal));
            string[] naming = [.. strings.Where(s => s.Contains(addOn, StringComparison.OrdinalIgnoreCase))];
            Assert.True(naming.Length == 0, $"the core's code names the add-on {addOn}: {string.Join(" | ", naming)}");
        }
    }
}
