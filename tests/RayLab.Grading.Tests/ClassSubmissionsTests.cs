namespace RayLab.Grading.Tests;

public sealed class ClassSubmissionsTests : IDisposable
{
    private readonly string _root = Directory.CreateTempSubdirectory("raylab-class-").FullName;

    public void Dispose() => Directory.Delete(_root, recursive: true);

    [Fact]
    public void AMoodleDownloadGivesEachStudentTheirFullNameAndParticipantId()
    {
        foreach (string folder in (string[])["Zażółć Gęślą Jaźń_12345_assignsubmission_file_", "Łucja Żak-Ćwik_7_assignsubmission_file_",
            "Łucja Żak-Ćwik_7_assignsubmission_onlinetext_", "Anna Maria O'Neil_99_assignsubmission_onlinetext_", ".hidden"])
        {
            Directory.CreateDirectory(Path.Combine(_root, folder));
        }

        IReadOnlyList<ClassSubmission> students = ClassSubmissions.Read(_root);
        Assert.Equal(["Anna Maria O'Neil", "Zażółć Gęślą Jaźń", "Łucja Żak-Ćwik"], students.Select(s => s.Name));
        Assert.Equal(["99", "12345", "7"], students.Select(s => s.ParticipantId));
        // A student with a file and an online text: the file's folder.
        Assert.Equal(Path.Combine(_root, "Łucja Żak-Ćwik_7_assignsubmission_file_"), students[2].Folder);
    }

    [Fact]
    public void APlainFolderOrGitHubClassroomClonesGiveEachFolderItsRow()
    {
        foreach (string folder in (string[])["lab2-jkowalski", "lab2-anowak", "Jan_Kowalski", ".git"])
        {
            Directory.CreateDirectory(Path.Combine(_root, folder));
        }

        IReadOnlyList<ClassSubmission> students = ClassSubmissions.Read(_root);
        Assert.Equal(["Jan_Kowalski", "lab2-anowak", "lab2-jkowalski"], students.Select(s => s.Name));
        Assert.All(students, s => Assert.Null(s.ParticipantId));
    }

    [Theory]
    [InlineData("Jan Kowalski_12345_assignsubmission_file_", true, "Jan Kowalski", "12345", "file")]
    [InlineData("Jan Kowalski_12345_assignsubmission_file", true, "Jan Kowalski", "12345", "file")]
    [InlineData("Ewa_Maria Nowak_3_assignsubmission_onlinetext_", true, "Ewa_Maria Nowak", "3", "onlinetext")]
    [InlineData("Jan Kowalski_assignsubmission_file_", false, null, null, null)]
    [InlineData("_12_assignsubmission_file_", false, null, null, null)]
    [InlineData("lab2-jkowalski", false, null, null, null)]
    public void MoodleFolderNamesAreRead(string name, bool moodle, string? fullName, string? id, string? plugin)
    {
        Assert.Equal(moodle, ClassSubmissions.TryParseMoodleFolder(name, out string? n, out string? i, out string? p));
        Assert.Equal(fullName, n);
        Assert.Equal(id, i);
        Assert.Equal(plugin, p);
    }

    [Fact]
    public void BadArgumentsNameTheirParameter()
    {
        Assert.Equal("participantId", Assert.Throws<ArgumentException>(() => new ClassSubmission("a", "b", "12a")).ParamName);
        Assert.Equal("name", Assert.Throws<ArgumentException>(() => new ClassSubmission(" ", "b", null)).ParamName);
        Assert.Throws<DirectoryNotFoundException>(() => ClassSubmissions.Read(Path.Combine(_root, "none")));
    }
}
