namespace RayLab.Reports.Output;

/// <summary>A command-line value that cannot be used; the message is the one line the user sees.</summary>
/// <param name="message">The message, starting with the option's name.</param>
internal sealed class UsageException(string message) : Exception(message);
