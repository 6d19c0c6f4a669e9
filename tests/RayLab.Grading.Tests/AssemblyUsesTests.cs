using RayLab.Grading.Tests.Fixtures;

namespace RayLab.Grading.Tests;

/// <summary>The metadata scan of this test assembly's lab-shaped fixtures (Fixtures/LabLike.cs), judged by a small list.</summary>
public sealed class AssemblyUsesTests
{
    private const string List = """
        {
          "sections": { "OwnCamera": "3.1", "DelegatingCamera": "3.2", "ReflectingCamera": "3.3" },
          "assemblies": [ "RayLab.Core" ],
          "allowed": [ "System.*", "RayLab.Double3", "RayLab.Ray", "System.Type::GetTypeFromHandle" ],
          "forbidden": {
            "System.Reflection.*": "reflection", "System.Type": "reflection", "System.Activator": "reflection",
            "System.Runtime.CompilerServices.UnsafeAccessorAttribute": "reflection"
          }
        }
        """;

    private static readonly AssemblyUses Uses = AssemblyUses.Read(typeof(OwnCamera).Assembly.Location);

    private static UseFinding[] Findings(string labType) =>
        [.. UseList.Parse(List, "test list").Check(Uses).Where(f => f.Use.LabType == labType)];

    [Fact]
    public void ACameraWrittenWithLabIsPartsAndTheBaseLibraryHasNoFinding()
    {
        Assert.Contains(Uses.Uses, u => u.LabType == nameof(OwnCamera) && u.Type == "RayLab.Double3" && u.Member == "Normalize");
        Assert.Empty(Findings(nameof(OwnCamera)));
    }

    [Fact]
    public void ACameraThatHandsItsWorkToRayLabsFailsItsSectionNamingWhatItUsed()
    {
        UseFinding[] findings = Findings(nameof(DelegatingCamera));
        Assert.All(findings, f => Assert.Equal(["3.2"], f.Sections));
        Assert.All(findings, f => Assert.Equal(UseRefusal.ToWrite, f.Verdict.Refusal));
        Assert.Contains(findings, f => f.Line(polish: false) == "3.2: DelegatingCamera.GetRay uses RayLab's Camera.GetImagePlane: the lab asks you to write it");
        Assert.Contains(findings, f => f.Line(polish: false) == "3.2: DelegatingCamera.GetRay uses RayLab's new OrthoCamera: the lab asks you to write it");
        Assert.Contains(findings, f => f.Line(polish: true) == "3.2: DelegatingCamera.GetRay używa ImagePlane.GetPixelRay z RayLab: to część laboratorium do napisania samodzielnie");
    }

    [Fact]
    public void ReflectionFailsTheSectionOfTheClassThatUsesItAndOfTheClassesThatReachAHelperThatDoes()
    {
        string[] own = [.. Findings(nameof(ReflectingCamera)).Select(f => f.Line(polish: false))];
        Assert.Contains("3.3: ReflectingCamera.Make uses reflection (Type.GetType), which the lab does not allow", own);
        Assert.Contains("3.3: ReflectingCamera.Make uses reflection (Activator.CreateInstance), which the lab does not allow", own);
        // The helper belongs to no section: it fails the section of the class whose lambda calls it.
        string[] helper = [.. Findings(nameof(ReflectionHelper)).Select(f => f.Line(polish: false))];
        Assert.Contains("3.3: ReflectionHelper.Call uses reflection (MethodBase.Invoke), which the lab does not allow", helper);
        Assert.Contains("3.3: ReflectionHelper.Call uses reflection (Type.GetMethod), which the lab does not allow", helper);
    }

    [Fact]
    public void NativeCodeAndUnsafeAccessorsInCodeNoSectionReachesFailEverySection()
    {
        UseFinding[] findings = Findings(nameof(Sneaky));
        Assert.Contains(findings, f => f.Use.Kind == UseKind.NativeMethod && f.Line(false) == "3.1, 3.2, 3.3: Sneaky.Pid uses native code (getpid (libc)), which the lab does not allow");
        Assert.Contains(findings, f => f.Use.Kind == UseKind.Attribute && f.Verdict == new UseVerdict(UseRefusal.Forbidden, "reflection") && f.Use.LabMethod == "Peek");
    }

    [Fact]
    public void TheBaseLibraryIsKnownByItsSigningKeyNotByItsNamespace()
    {
        Assert.Contains(Uses.Uses, u => u.Type == "System.Activator" && u.FromBaseLibrary);
        Assert.Contains(Uses.Uses, u => u.Assembly == "RayLab.Core" && !u.FromBaseLibrary);
        // A type named like the base library's from an assembly the list does not name is refused as unlisted.
        var fake = new ForeignUse("OwnCamera", "GetRay", "Evil", "System.Math", "Sqrt", UseKind.Member);
        Assert.Equal(UseRefusal.NotListed, UseList.Parse(List, "test list").Judge(fake).Refusal);
        Assert.Equal(UseRefusal.None, UseList.Parse(List, "test list").Judge(fake with { FromBaseLibrary = true }).Refusal);
    }
}
