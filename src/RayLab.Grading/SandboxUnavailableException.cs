namespace RayLab.Grading;

/// <summary>
/// The sandbox, or one of its limits, cannot hold on this machine (<see cref="GradeSandbox.Create(bool, IReadOnlyList{string}, string, GradeLimits?)"/>), or a lab's copy
/// cannot be given its disk limit: the message says what is missing and the option that grades without it.
/// </summary>
public sealed class SandboxUnavailableException : Exception
{
    /// <summary>Creates the exception with no message.</summary>
    public SandboxUnavailableException()
    {
    }

    /// <summary>Creates the exception with its message.</summary>
    /// <param name="message">What is missing, and the option that grades without it.</param>
    public SandboxUnavailableException(string message)
        : base(message)
    {
    }

    /// <summary>Creates the exception with its message and the exception that caused it.</summary>
    /// <param name="message">What is missing, and the option that grades without it.</param>
    /// <param name="innerException">The cause.</param>
    public SandboxUnavailableException(string message, Exception innerException)
        : base(message, innerException)
    {
    }
}
