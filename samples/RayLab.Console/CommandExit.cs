using RayLab.Scenes;
using RayLab.Reports.Output;

namespace RayLab.Cli;

/// <summary>
/// The one path by which every command's work becomes an exit code and, when it fails, one line on standard error
/// with no stack trace: 0 done, 1 bad input or a failed run, 2 a bad command line, 70 a bug, 130 cancelled.
/// </summary>
public static class CommandExit
{
    /// <summary>The work was done.</summary>
    public const int Done = 0;

    /// <summary>Bad input (a scene file, a path, a value) or a run that could not finish.</summary>
    public const int Failed = 1;

    /// <summary>The command line does not parse.</summary>
    public const int BadCommandLine = 2;

    /// <summary>A bug: an exception no input explains (EX_SOFTWARE).</summary>
    public const int InternalError = 70;

    /// <summary>
    /// Runs a command's work and turns what it throws for bad input, cancellation or lack of memory into one line on
    /// <paramref name="stderr"/> and the exit code; anything else is a bug and goes on to <see cref="Program.Run"/>,
    /// which reports it as <see cref="InternalError"/>.
    /// </summary>
    /// <param name="stderr">Where the one line goes.</param>
    /// <param name="work">The command's work; returns its exit code (<see cref="Done"/> unless it chose another).</param>
    /// <param name="cancelled">What a cancelled run left undone, e.g. "out.png not written".</param>
    /// <param name="tooLarge">What ran out of memory, e.g. "render scene.json at the requested size".</param>
    /// <param name="cancellation">The run's cancellation: an <see cref="OperationCanceledException"/> counts as cancelled only when it was requested.</param>
    /// <param name="alsoBadInput">Further exceptions this command's input explains (the library's argument checks, say).</param>
    /// <returns>The exit code.</returns>
    public static int Run(
        TextWriter stderr, Func<int> work, string cancelled, string tooLarge, CancellationToken cancellation, Func<Exception, bool>? alsoBadInput = null)
    {
        try
        {
            return work();
        }
        catch (OperationCanceledException) when (cancellation.IsCancellationRequested)
        {
            stderr.WriteLine($"raylab: cancelled; {SceneFileException.OneLine(cancelled)}");
            return Program.CancelledExitCode;
        }
        catch (Exception e) when (IsBadInput(e) || alsoBadInput?.Invoke(e) == true)
        {
            stderr.WriteLine($"raylab: error: {SceneFileException.OneLine(e.Message)}");
            return Failed;
        }
        catch (OutOfMemoryException)
        {
            stderr.WriteLine($"raylab: error: not enough memory to {SceneFileException.OneLine(tooLarge)}");
            return Failed;
        }
    }

    /// <summary>One line for an exception no input explains, and <see cref="InternalError"/>.</summary>
    /// <param name="stderr">Where the line goes.</param>
    /// <param name="e">The exception.</param>
    /// <returns><see cref="InternalError"/>.</returns>
    public static int Bug(TextWriter stderr, Exception e)
    {
        stderr.WriteLine($"raylab: internal error: {e.GetType().Name}: {SceneFileException.OneLine(e.Message)}");
        return InternalError;
    }

    private static bool IsBadInput(Exception e) =>
        e is SceneFileException or UsageException or IOException or UnauthorizedAccessException or NotSupportedException
            or FormatException or InvalidDataException;
}
