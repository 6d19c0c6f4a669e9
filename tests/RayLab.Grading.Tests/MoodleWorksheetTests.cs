using System.Text;

namespace RayLab.Grading.Tests;

public sealed class MoodleWorksheetTests
{
    private const string Header = "Identifier,Full name,Email address,Status,Grade,Maximum Grade,Grade can be changed,Last modified (submission),Last modified (grade),Feedback comments";

    private static readonly string[] Rows =
    [
        "Participant 101,Zażółć Gęślą,zg@example.edu,Submitted for grading,,10.00,Yes,\"Friday, 6 November 2026, 10:00 AM\",-,",
        "Participant 104,Piotr Brak,pb@example.edu,No submission,,10.00,Yes,-,-,\"Brak pracy, \"\"przypomnieć\"\"\npo zajęciach\"",
        "Participant 102,\"Kowalski, Jan\",jk@example.edu,Submitted for grading,3.00,10.00,Yes,-,-,old",
    ];

    [Theory]
    [InlineData(true, "\n")]
    [InlineData(false, "\r\n")]
    public void FillingKeepsEveryByteOfTheRowsNotGradedTheEncodingAndTheLineEndings(bool bom, string newLine)
    {
        string text = string.Join(newLine, [Header, .. Rows]) + newLine;
        byte[] bytes = Encoding(bom).GetPreamble().Concat(Encoding(bom).GetBytes(text)).ToArray();
        MoodleWorksheet sheet = MoodleWorksheet.Parse(bytes, "grades.csv");
        Assert.Equal([("101", "Zażółć Gęślą"), ("104", "Piotr Brak"), ("102", "Kowalski, Jan")], sheet.Participants);
        Assert.Equal(10, sheet.MaximumGrade);

        byte[] filled = sheet.Fill(new Dictionary<string, WorksheetGrade>
        {
            ["101"] = new(9.5, "Niezaliczone: 3.1: Assert.Equal() Failure: \"a\", b"),
            ["102"] = new(0, "Archiwum odrzucone: lab.zip: wpis ../x wychodzi poza folder."),
        });

        Assert.Equal(bom, filled.AsSpan().StartsWith(new byte[] { 0xEF, 0xBB, 0xBF }));
        string written = new UTF8Encoding(false).GetString(filled, bom ? 3 : 0, filled.Length - (bom ? 3 : 0));
        string expected = string.Join(newLine,
        [
            Header,
            "Participant 101,Zażółć Gęślą,zg@example.edu,Submitted for grading,9.50,10.00,Yes,\"Friday, 6 November 2026, 10:00 AM\",-,\"Niezaliczone: 3.1: Assert.Equal() Failure: \"\"a\"\", b\"",
            Rows[1],
            "Participant 102,\"Kowalski, Jan\",jk@example.edu,Submitted for grading,0.00,10.00,Yes,-,-,Archiwum odrzucone: lab.zip: wpis ../x wychodzi poza folder.",
        ]) + newLine;
        Assert.Equal(expected, written);

        // Nothing to fill: the same bytes.
        Assert.Equal(bytes, sheet.Fill(new Dictionary<string, WorksheetGrade>()));
    }

    [Fact]
    public void AFileWithoutAFinalLineBreakAndWithDecimalCommasKeepsBoth()
    {
        string text = Header + "\nParticipant 7,Ewa Nowak,e@x,Submitted,,\"10,00\",Yes,-,-,";
        MoodleWorksheet sheet = MoodleWorksheet.Parse(System.Text.Encoding.UTF8.GetBytes(text), "grades.csv");
        string written = System.Text.Encoding.UTF8.GetString(sheet.Fill(new Dictionary<string, WorksheetGrade> { ["7"] = new(8.25, "Wszystkie sekcje zaliczone.") }));
        Assert.Equal(Header + "\nParticipant 7,Ewa Nowak,e@x,Submitted,\"8,25\",\"10,00\",Yes,-,-,Wszystkie sekcje zaliczone.", written);
        Assert.Equal("7", sheet.ParticipantOf("Ewa Nowak"));
        Assert.Equal(10, sheet.MaximumGrade);
        Assert.Null(sheet.ParticipantOf("Jan Kowalski"));
    }

    [Theory]
    [InlineData("Identifier,Full name,Grade\nParticipant 1,A,\n", "grades.csv: no column 'Feedback comments' in the header (Identifier, Full name, Grade); give the assignment's grading worksheet as Moodle writes it")]
    [InlineData("", "grades.csv: the file is empty; download the grading worksheet from Moodle")]
    [InlineData("Identifier,Grade,Feedback comments\nParticipant 1,,\"open\n", "grades.csv: line 2: a quoted cell is never closed")]
    public void ABadWorksheetIsOneLineNamingTheFile(string text, string message)
    {
        MoodleWorksheetException e = Assert.Throws<MoodleWorksheetException>(() => MoodleWorksheet.Parse(System.Text.Encoding.UTF8.GetBytes(text), "grades.csv"));
        Assert.Equal(message, e.Message);
    }

    [Fact]
    public void AWorksheetThatIsNotUtf8IsRefused()
    {
        byte[] latin2 = [.. System.Text.Encoding.ASCII.GetBytes("Identifier,Grade,Feedback comments\nParticipant 1,,"), 0xB3, (byte)'\n'];
        MoodleWorksheetException e = Assert.Throws<MoodleWorksheetException>(() => MoodleWorksheet.Parse(latin2, "grades.csv"));
        Assert.Equal("grades.csv: not UTF-8; download the worksheet from Moodle again, unchanged", e.Message);
    }

    private static UTF8Encoding Encoding(bool bom) => new(bom);
}
