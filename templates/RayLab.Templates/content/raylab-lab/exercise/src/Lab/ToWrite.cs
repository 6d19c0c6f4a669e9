namespace MyLab;

#if (en)
/// <summary>The exception every part of the lab throws until you write it: it names the lab's section.</summary>
#else
/// <summary>Wyjątek, który rzuca każda część laboratorium, dopóki jej nie napiszesz: podaje sekcję instrukcji.</summary>
#endif
internal static class ToWrite
{
    public static NotImplementedException Section(string section, string what) =>
#if (en)
        new($"{section} {Sections.Title(section)}: still to write — {what}");
#else
        new($"{section} {Sections.Title(section)}: jeszcze do napisania — {what}");
#endif
}

#if (en)
/// <summary>The lab's sections, as the lab numbers and names them.</summary>
#else
/// <summary>Sekcje instrukcji, z numerami i nazwami z instrukcji.</summary>
#endif
internal static class Sections
{
    public static readonly (string Id, string Title, string Classes)[] All =
    [
#if (en)
        ("2.1", "Intensity", "LightIntensity"),
        ("2.2", "Image", "LabImage"),
        ("3", "Camera", "LabCamera"),
        ("3.1", "Orthographic camera", "LabOrthoCamera"),
        ("3.2", "Perspective camera", "LabPerspectiveCamera"),
        ("4.1.1", "Regular sampling", "LabRegularSampler"),
        ("4.1.2", "Random sampling", "LabRandomSampler"),
        ("4.1.3", "Jittered sampling", "LabJitteredSampler"),
        ("4.1.4", "Adaptive sampling", "LabAdaptiveSampler"),
        ("5", "Task: the render loop", "LabRenderer"),
#else
        ("2.1", "Natężenie", "LightIntensity"),
        ("2.2", "Obraz", "LabImage"),
        ("3", "Kamera", "LabCamera"),
        ("3.1", "Kamera ortogonalna", "LabOrthoCamera"),
        ("3.2", "Kamera perspektywiczna", "LabPerspectiveCamera"),
        ("4.1.1", "Próbkowanie regularne", "LabRegularSampler"),
        ("4.1.2", "Próbkowanie losowe", "LabRandomSampler"),
        ("4.1.3", "Próbkowanie jittered (losowe nieregularne)", "LabJitteredSampler"),
        ("4.1.4", "Próbkowanie adaptacyjne", "LabAdaptiveSampler"),
        ("5", "Zadanie: pętla renderowania", "LabRenderer"),
#endif
    ];

    public static string Title(string id) => All.First(s => s.Id == id).Title;
}
