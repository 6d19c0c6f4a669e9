namespace RayLab.Grading;

/// <summary>
/// A <see cref="GradeRequest"/> that <see cref="GradeJob.Run"/> cannot grade, found before any submission runs (or,
/// for the report's folder, when the report is written): the message starts with the option as <c>raylab grade</c>
/// spells it (<see cref="Option"/>: <c>--jobs</c>, <c>--checks</c>, <c>submissions</c>, …), then what is wrong.
/// </summary>
public sealed class GradeRequestException : Exception
{
    /// <summary>Creates the exception with no message.</summary>
    public GradeRequestException()
    {
    }

    /// <summary>Creates the exception with its message.</summary>
    /// <param name="message">The option, a colon, and what is wrong with it: <c>--jobs: expected a count ≥ 1, got 0</c>.</param>
    public GradeRequestException(string message)
        : base(message)
    {
    }

    /// <summary>Creates the exception with its message and the exception that caused it.</summary>
    /// <param name="message">The option, a colon, and what is wrong with it.</param>
    /// <param name="innerException">The cause.</param>
    public GradeRequestException(string message, Exception innerException)
        : base(message, innerException)
    {
    }

    /// <summary>
    /// The option the message names (<c>--jobs</c>, <c>--checks</c>, <c>submissions</c>, …): the message's text before
    /// its first colon, or empty where the message names none.
    /// </summary>
    public string Option => Message.IndexOf(": ", StringComparison.Ordinal) is int colon and > 0 && !Message[..colon].Contains(' ', StringComparison.Ordinal)
        ? Message[..colon]
        : "";
}
