namespace RayLab.PrecisionReport;

/// <summary>One row of the report: how each way of testing the sphere did on one hard case.</summary>
/// <param name="Case">The case.</param>
/// <param name="Pixels">Pixels in the image (one ray through each centre).</param>
/// <param name="ExactHits">Pixels whose ray hits the sphere by the exact decision.</param>
/// <param name="NaiveFloatWrong">Pixels where the textbook b² − 4ac test in float disagrees with the exact decision.</param>
/// <param name="RtgFloatWrong">Pixels where Ray Tracing Gems' test in float disagrees.</param>
/// <param name="RayLab">RayLab's renderer (Renderer.Render, one sample at each centre) with each kernel setting, Auto first.</param>
/// <param name="DoubleWrong">Pixels where Ray Tracing Gems' test in plain double disagrees.</param>
/// <param name="NaiveFloatError">The worst surface error | |p − C| − R | of the textbook float test's hit points.</param>
/// <param name="RtgFloatError">The same for Ray Tracing Gems in float.</param>
/// <param name="DoubleError">The same for Ray Tracing Gems in plain double.</param>
/// <param name="AccurateError">The same for RayLab's <c>TryIntersectAccurate</c>.</param>
/// <param name="DoubleErrorUlps">The plain-double surface error in ulp(|p|), worst over the hits.</param>
/// <param name="AccurateErrorUlps">RayLab's accurate surface error in ulp(|p|), worst over the hits.</param>
public sealed record CaseResult(
    HardCase Case, int Pixels, int ExactHits, int NaiveFloatWrong, int RtgFloatWrong, IReadOnlyList<KernelRun> RayLab, int DoubleWrong,
    double NaiveFloatError, double RtgFloatError, double DoubleError, double AccurateError, double DoubleErrorUlps, double AccurateErrorUlps)
{
    /// <summary>Wrong pixels of the image users get (<see cref="RayLab.RenderKernel.Auto"/>).</summary>
    public int RayLabWrong => RayLab[0].Wrong;

    /// <summary>The most wrong pixels over every kernel setting.</summary>
    public int RayLabWorstWrong => RayLab.Max(k => k.Wrong);
}
