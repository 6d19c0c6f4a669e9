namespace RayLab.Reports.Comparison;

/// <summary>One stage of a comparison and the wall time it took.</summary>
/// <param name="Name">The stage, e.g. <c>renders</c> or <c>FLIP</c>.</param>
/// <param name="Time">Its wall time, over all its calls.</param>
/// <param name="Calls">How many calls the time adds up.</param>
public sealed record CompareStage(string Name, TimeSpan Time, int Calls);
