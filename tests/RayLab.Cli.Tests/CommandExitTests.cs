using RayLab.Reports.Output;
using RayLab.Scenes;

namespace RayLab.Cli.Tests;

/// <summary>The one path by which every command's work becomes an exit code and at most one line on standard error.</summary>
public sealed class CommandExitTests
{
    private static (int Code, string Err) Outcome(Func<int> work, Func<Exception, bool>? alsoBadInput = null) =>
        CancelledOutcome(work, alsoBadInput, TestContext.Current.CancellationToken);

    private static (int Code, string Err) CancelledOutcome(Func<int> work, Func<Exception, bool>? alsoBadInput, CancellationToken cancellation)
    {
        var stderr = new StringWriter();
        int code = CommandExit.Run(stderr, work, "out.png not written", "render big.json at the requested size", cancellation, alsoBadInput);
        return (code, stderr.ToString());
    }

    [Fact]
    public void Work_that_finishes_gives_its_own_code_and_no_line()
    {
        Assert.Equal((0, ""), Outcome(() => CommandExit.Done));
        Assert.Equal((3, ""), Outcome(() => 3));
    }

    public static TheoryData<Exception> BadInput() =>
    [
        new UsageException("--samples: expected 1 to 1024, got 0"),
        new IOException("disk full"), new UnauthorizedAccessException("out: read-only"), new NotSupportedException("'.gif'"),
        new FormatException("table.csv: line 2"), new InvalidDataException("x.png: not a picture"),
    ];

    [Theory]
    [MemberData(nameof(BadInput))]
    public void Bad_input_is_one_line_with_the_message_and_code_1(Exception thrown)
    {
        (int code, string err) = Outcome(() => throw thrown);

        Assert.Equal(CommandExit.Failed, code);
        Assert.Equal($"raylab: error: {SceneFileException.OneLine(thrown.Message)}", Assert.Single(err.TrimEnd('\n').Split('\n')));
    }

    [Fact]
    public void A_requested_cancellation_is_one_line_saying_what_was_left_undone_and_code_130()
    {
        using var cancel = new CancellationTokenSource();
        cancel.Cancel();

        (int code, string err) = CancelledOutcome(() => throw new OperationCanceledException(cancel.Token), null, cancel.Token);

        Assert.Equal((Program.CancelledExitCode, "raylab: cancelled; out.png not written\n"), (code, err.ReplaceLineEndings("\n")));
    }

    [Fact]
    public void Lack_of_memory_is_one_line_saying_what_did_not_fit_and_code_1()
    {
        (int code, string err) = Outcome(() => throw new InsufficientMemoryException()); // an OutOfMemoryException the code may throw itself

        Assert.Equal((1, "raylab: error: not enough memory to render big.json at the requested size\n"), (code, err.ReplaceLineEndings("\n")));
    }

    [Fact]
    public void A_bug_is_not_bad_input_it_goes_on_to_program_run_which_gives_70_and_one_line()
    {
        Assert.Throws<InvalidOperationException>(() => Outcome(() => throw new InvalidOperationException("a bug")));
        Assert.Throws<OperationCanceledException>(() => Outcome(() => throw new OperationCanceledException())); // not requested
        (int code, string err) = Outcome(() => throw new ArgumentException("bad width"), alsoBadInput: e => e is ArgumentException);
        Assert.Equal((1, "raylab: error: bad width"), (code, err.TrimEnd()));

        var stderr = new StringWriter();
        Assert.Equal(CommandExit.InternalError, CommandExit.Bug(stderr, new InvalidOperationException("a\nbug")));
        Assert.Equal($"raylab: internal error: InvalidOperationException: {SceneFileException.OneLine("a\nbug")}", stderr.ToString().TrimEnd());
    }
}
