namespace MyLab.Tests;

#if (en)
/// <summary>
/// How many of the lab's parts are written, the one place dotnet test lists the sections still to write: their own
/// checks are skipped, each with one line. Fails until every part is written, so dotnet test says what is left.
/// It asks the program's own probe (src/Lab/Progress.cs, as dotnet run -- check does), so it is built only beside
/// src/Lab: the grader builds the checks against your built lab alone, and counts what each section's checks say.
/// </summary>
#else
/// <summary>
/// Ile części laboratorium jest napisanych: jedyne miejsce, w którym dotnet test wypisuje sekcje jeszcze do
/// napisania (ich własne testy są pominięte, każdy z jednym wierszem). Nie przechodzi, dopóki wszystkie części nie są
/// napisane, więc dotnet test mówi, co zostało. Pyta sprawdzenie samego programu (src/Lab/Progress.cs, jak dotnet
/// run -- check), więc buduje się tylko obok src/Lab: ocenianie buduje testy z samym zbudowanym laboratorium i liczy,
/// co mówią testy każdej sekcji.
/// </summary>
#endif
public sealed class LabProgress(ITestOutputHelper output)
{
    [Fact(DisplayName = Msg.PartsWrittenName)]
    public void PartsWritten()
    {
        var states = Progress.Probe();
        var left = states.Where(s => s.State == Progress.State.ToWrite).ToList();
        string counted = Msg.PartsWritten(states.Count - left.Count, states.Count);
        output.WriteLine(counted);
        if (left.Count > 0)
        {
            string list = string.Join("\n", left.Select(s => $"  {s.Id} {s.Title} ({s.Classes}): {s.Detail}"));
            throw new Xunit.Sdk.ProgressReport(Msg.StillToWrite(counted, list, left[0].Id, left[0].Title, left[0].Classes.Split(',')[0]));
        }
    }
}
