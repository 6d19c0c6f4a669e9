namespace RayLab.Grading.Tests;

public sealed class UseListTests
{
    private static UseVerdict Judge(string json, string type, string member, string assembly = "System.Runtime") =>
        UseList.Parse(json, "t.json").Judge(new ForeignUse("C", "M", assembly, type, member, UseKind.Member) { FromBaseLibrary = assembly.StartsWith("System", StringComparison.Ordinal) });

    [Theory]
    // a member rule beats a type rule, which beats a namespace rule
    [InlineData("System.Type", "GetTypeFromHandle", UseRefusal.None)]
    [InlineData("System.Type", "GetMethod", UseRefusal.Forbidden)]
    [InlineData("System.Reflection.MethodBase", "Invoke", UseRefusal.Forbidden)]
    [InlineData("System.Reflection.MemberInfo", "get_Name", UseRefusal.None)]
    [InlineData("System.Math", "Sqrt", UseRefusal.None)]
    // a nested type follows its outer type's rule
    [InlineData("System.Type+Nested", "X", UseRefusal.Forbidden)]
    // a namespace rule does not match a longer name that only starts the same way
    [InlineData("System.ReflectionX.Thing", "X", UseRefusal.None)]
    public void TheMostSpecificRuleDecides(string type, string member, UseRefusal expected)
    {
        const string json = """
            { "allowed": ["System.*", "System.Type::GetTypeFromHandle", "System.Reflection.MemberInfo::get_Name"],
              "forbidden": { "System.Reflection.*": "reflection", "System.Type": "reflection" } }
            """;
        Assert.Equal(expected, Judge(json, type, member).Refusal);
    }

    [Fact]
    public void ForbiddenWinsATieAndAnUnlistedRayLabMemberIsTheLabsToWrite()
    {
        Assert.Equal(UseRefusal.Forbidden, Judge("""{ "allowed": ["System.IO"], "forbidden": { "System.IO": "files" } }""", "System.IO", "X").Refusal);
        Assert.Equal(UseRefusal.ToWrite, Judge("""{ "assemblies": ["RayLab.Core"], "allowed": ["RayLab.Double3"] }""", "RayLab.OrthoCamera", ".ctor", "RayLab.Core").Refusal);
        Assert.Equal(UseRefusal.None, Judge("""{ "assemblies": ["RayLab.Core"], "allowed": ["RayLab.Double3"] }""", "RayLab.Double3", "Cross", "RayLab.Core").Refusal);
        Assert.Equal(UseRefusal.NotListed, Judge("""{ "allowed": ["Other.*"] }""", "Other.Thing", "X", "Other").Refusal);
    }

    [Theory]
    // the exercise lab's own list: the skeleton's scan of itself (RayLab.Grading.Uses), and nothing of the grader,
    // whose package (RayLab.Grading) is no assembly a lab may use
    [InlineData("RayLab.Grading.UseList", "Load", UseRefusal.None)]
    [InlineData("RayLab.Grading.AssemblyUses", "Read", UseRefusal.None)]
    [InlineData("RayLab.Grading.UseFinding", "Message", UseRefusal.None)]
    [InlineData("RayLab.Grading.GradeSandbox", "Run", UseRefusal.NotListed)]
    [InlineData("RayLab.Grading.SafeZip", "Extract", UseRefusal.NotListed)]
    [InlineData("RayLab.OrthoCamera", "GetImagePlane", UseRefusal.ToWrite)]
    [InlineData("System.Diagnostics.Process", "Start", UseRefusal.Forbidden)]
    public void TheExerciseLabsListAllowsItsScanAndNothingElseOfTheGrader(string type, string member, UseRefusal expected)
    {
        string list = Path.Combine(AppContext.BaseDirectory, "exercise-uses.json");
        string assembly = type is "RayLab.Grading.UseList" or "RayLab.Grading.AssemblyUses" or "RayLab.Grading.UseFinding" ? "RayLab.Grading.Uses" : type.StartsWith("RayLab.Grading", StringComparison.Ordinal) ? "RayLab.Grading" : type.StartsWith("RayLab", StringComparison.Ordinal) ? "RayLab.Core" : "System.Runtime";
        Assert.Equal(expected, Judge(File.ReadAllText(list), type, member, assembly).Refusal);
    }

    [Theory]
    [InlineData("[]", "t.json: expected a JSON object")]
    [InlineData("""{ "allowed": "System.*" }""", "t.json: allowed: expected an array of strings")]
    [InlineData("""{ "allowed": ["System.*.Linq"] }""", "t.json: allowed: 'System.*.Linq' is not a rule: expected Namespace.*, Namespace.Type or Namespace.Type::Member")]
    [InlineData("""{ "forbidden": { "System.Type": "" } }""", "t.json: forbidden.System.Type: expected a non-empty string")]
    [InlineData("""{ "sections": { "LabImage": 2 } }""", "t.json: sections.LabImage: expected a non-empty string")]
    public void ABadListIsAnErrorNamingTheFileAndTheField(string json, string message)
    {
        FormatException e = Assert.Throws<FormatException>(() => UseList.Parse(json, "t.json"));
        Assert.Equal(message, e.Message);
    }

    [Fact]
    public void NotJsonIsAnErrorNamingTheFile()
    {
        FormatException e = Assert.Throws<FormatException>(() => UseList.Parse("{", "t.json"));
        Assert.StartsWith("t.json: not valid JSON", e.Message, StringComparison.Ordinal);
    }
}

public sealed class ProgramOnlyTests
{
    [Fact]
    public void AProgramOnlyClassIsJudgedOnlyWhereASectionsClassReachesIt()
    {
        // The fixtures' ReflectionHelper is reached from ReflectingCamera; Sneaky is reached from no class.
        const string json = """
            { "sections": { "ReflectingCamera": "own" }, "programOnly": ["ReflectionHelper", "Sneaky"],
              "allowed": ["System.*"], "forbidden": { "System.Reflection.*": "reflection", "System.Type": "reflection",
              "System.Runtime.CompilerServices.UnsafeAccessorAttribute": "reflection" } }
            """;
        IReadOnlyList<UseFinding> findings = UseList.Parse(json, "t.json").Check(AssemblyUses.Read(typeof(UseListTests).Assembly.Location));
        Assert.Contains(findings, f => f.Use.LabType == "ReflectionHelper" && f.Sections.SequenceEqual(["own"]));
        Assert.DoesNotContain(findings, f => f.Use.LabType == "Sneaky");
    }
}
