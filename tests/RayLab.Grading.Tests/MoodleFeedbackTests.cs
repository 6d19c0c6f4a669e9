namespace RayLab.Grading.Tests;

public sealed class MoodleFeedbackTests
{
    [Fact]
    public void EverySectionPassed() =>
        Assert.Equal("Wszystkie sekcje zaliczone.", MoodleFeedback.Polish([], null, []));

    [Fact]
    public void TheFailedSectionsEachWithTheirFirstMessageOnOneLine() =>
        Assert.Equal("Program przekroczył limit czasu; brak obrazów. Niezaliczone: 2.2: Assert.Equal() Failure Expected: 255 Actual: 256; 3.1.",
            MoodleFeedback.Polish(["program time limit", "pictures missing"], null,
                [new FailedSection("2.2", "Assert.Equal() Failure\n  Expected: 255\n  Actual:   256"), new FailedSection("3.1", null)]));

    [Fact]
    public void ARefusedUploadSaysWhyInPolish() =>
        Assert.Equal("Archiwum odrzucone: lab.zip: wpis ../x wychodzi poza folder.",
            MoodleFeedback.Polish(["zip refused: lab.zip: entry ../x climbs out of the folder"], "Archiwum odrzucone: lab.zip: wpis ../x wychodzi poza folder", []));

    [Fact]
    public void ALongMessageIsCut()
    {
        string feedback = MoodleFeedback.Polish(["program failed (exit 134)"], null, [new FailedSection("5", new string('x', 500))]);
        Assert.StartsWith("Program zakończył się błędem (kod 134). Niezaliczone: 5: xxx", feedback, StringComparison.Ordinal);
        Assert.EndsWith("x….", feedback, StringComparison.Ordinal);
        Assert.True(feedback.Length < 300);
    }
}
