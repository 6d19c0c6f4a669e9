using RayLab.Grading;
using static MyLab.Tests.Check;

namespace MyLab.Tests;

#if (en)
/// <summary>
/// Every section: its classes use only what the lab allows (uses.json): Lab I's parts from RayLab (vectors, ray,
/// sphere, scene, the scene file) and the base library; not RayLab's own intensity, image, cameras or samplers in
/// place of yours, and no reflection, native code or processes. Read from the built lab (src/Lab) with
/// RayLab.Grading, which the grader uses with the same list.
/// </summary>
#else
/// <summary>
/// Każda sekcja: jej klasy używają tylko tego, na co laboratorium pozwala (uses.json): części z Lab I z RayLab
/// (wektory, promień, kula, scena, plik sceny) i biblioteki standardowej; nie natężenia, obrazu, kamer ani próbkowania
/// z RayLab w miejsce Twoich, bez refleksji, kodu natywnego i procesów. Odczytane ze zbudowanego laboratorium
/// (src/Lab) przez RayLab.Grading, którego z tą samą listą używa ocenianie.
/// </summary>
#endif
public sealed class UsesChecks(ITestOutputHelper output)
{
    private static readonly UseList List = UseList.Load(Path.Combine(AppContext.BaseDirectory, "uses.json"));

    private static readonly Lazy<IReadOnlyList<UseFinding>> Findings =
        new(() => List.Check(AssemblyUses.Read(typeof(LightIntensity).Assembly.Location)));

#if (en)
    /// <summary>One check per section of the list, named and marked with its section.</summary>
#else
    /// <summary>Jedno sprawdzenie na sekcję listy, nazwane i oznaczone swoją sekcją.</summary>
#endif
    public static IEnumerable<TheoryDataRow<string>> Sections =>
        List.Sections.Values.Distinct(StringComparer.Ordinal).Select(id => new TheoryDataRow<string>(id)
        {
            TestDisplayName = $"{id} {Msg.OwnCode}",
            Traits = new Dictionary<string, HashSet<string>> { ["Section"] = [id] },
        });

    [Theory]
    [MemberData(nameof(Sections))]
    public void OnlyWhatTheLabAllows(string section) => Run(output, () =>
    {
        string[] lines = [.. Findings.Value.Where(f => f.Sections.Contains(section)).Select(Msg.Finding)];
        Assert.True(lines.Length == 0, string.Join("\n", lines));
        output.WriteLine(Msg.NothingOffTheList(section));
    });
}
