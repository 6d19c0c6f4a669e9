namespace RayLab.Gpu;

/// <summary>No GPU can be opened here (no CUDA driver, or no device); the message is one line a command can print.</summary>
public sealed class GpuUnavailableException : Exception
{
    /// <summary>Creates the exception with its one-line message.</summary>
    public GpuUnavailableException()
        : base("No CUDA GPU was found.")
    {
    }

    /// <summary>Creates the exception with its one-line message.</summary>
    /// <param name="message">What is missing.</param>
    public GpuUnavailableException(string message)
        : base(message)
    {
    }

    /// <summary>Creates the exception with its one-line message and the error behind it.</summary>
    /// <param name="message">What is missing.</param>
    /// <param name="innerException">The error behind it.</param>
    public GpuUnavailableException(string message, Exception innerException)
        : base(message, innerException)
    {
    }
}
