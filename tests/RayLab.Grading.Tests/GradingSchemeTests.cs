using System.Text.Json;

namespace RayLab.Grading.Tests;

public sealed class GradingSchemeTests
{
    private static GradingScheme Read(string json)
    {
        using JsonDocument document = JsonDocument.Parse(json);
        return GradingScheme.Read(document.RootElement, "kit/checks/exercise/grading.json");
    }

    [Fact]
    public void TodaysFileWithoutPointsGivesEverySectionOnePointAndThePicturesNone()
    {
        GradingScheme scheme = Read("""{ "kind": "exercise", "raylabVersion": "1.0.0", "pictures": { "perspective": "out/p.png" }, "timedMethod": "adaptive" }""");
        Assert.Null(scheme.SectionPoints);
        Assert.Equal(3, scheme.MaxGrade(["2.1", "2.2", "3"], 2));
        Assert.Equal(2, scheme.Grade(new Dictionary<string, string> { ["2.1"] = "pass", ["2.2"] = "fail", ["3"] = "pass" }, [(0.1, 0.01), (0.1, 0.01)]));
    }

    [Fact]
    public void TheGradeIsThePointsOfThePassingSectionsAndOfThePicturesWithinTheThresholds()
    {
        GradingScheme scheme = Read("""{ "points": { "2.1": 1.5, "3.1": 2, "5": 4 }, "picturePoints": 1, "pictureThresholds": { "rmse": 1.0, "flip": 0.02 } }""");
        Assert.Equal(7.5 + 2, scheme.MaxGrade(["2.1", "3.1", "5", "own"], 2));
        var sections = new Dictionary<string, string> { ["2.1"] = "pass", ["3.1"] = "timeout", ["5"] = "pass", ["own"] = "pass" };
        Assert.Equal(5.5 + 1, scheme.Grade(sections, [(0.9, 0.019), (1.1, 0.01)]));
        Assert.Equal(5.5, scheme.Grade(sections, [(double.NaN, double.NaN), (0.5, 0.03)]));
    }

    [Theory]
    [InlineData("""{ "points": [1, 2] }""", "points: expected an object of section → points, got array")]
    [InlineData("""{ "points": { "3.1": -1 } }""", "points.3.1: expected points ≥ 0, got -1")]
    [InlineData("""{ "points": { "3.1": "two" } }""", "points.3.1: expected points ≥ 0, got the string \"two\"")]
    [InlineData("""{ "picturePoints": true }""", "picturePoints: expected points ≥ 0, got true")]
    [InlineData("""{ "pictureThresholds": { "rmse": 0 } }""", "pictureThresholds.rmse: expected 8-bit levels > 0, got 0")]
    [InlineData("""{ "pictureThresholds": { "flip": 1.5 } }""", "pictureThresholds.flip: expected a mean FLIP in (0, 1], got 1.5")]
    [InlineData("""{ "pictureThresholds": { "FLIP": 0.1 } }""", "pictureThresholds.FLIP: expected rmse or flip")]
    [InlineData("""[]""", "(root): expected an object, got array")]
    public void ABadValueNamesTheFileAndTheField(string json, string message)
    {
        GradingFileException e = Assert.Throws<GradingFileException>(() => Read(json));
        Assert.Equal($"kit/checks/exercise/grading.json: {message}", e.Message);
    }

    [Fact]
    public void TheConstructorNamesTheBadParameter()
    {
        Assert.Equal("maxFlip", Assert.Throws<ArgumentOutOfRangeException>(() => new GradingScheme(null, 0, 1, 0)).ParamName);
        Assert.Equal("sectionPoints", Assert.Throws<ArgumentOutOfRangeException>(() => new GradingScheme(new Dictionary<string, double> { ["a"] = double.NaN }, 0, 1, 0.1)).ParamName);
    }
}
