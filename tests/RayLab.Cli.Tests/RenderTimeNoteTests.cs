namespace RayLab.Cli.Tests;

/// <summary>The render time the console prints says what it includes.</summary>
public sealed class RenderTimeNoteTests
{
    [Fact]
    public void Under_the_jit_the_time_says_it_includes_compilation_unless_a_warm_up_ran_first()
    {
        Assert.Equal("; JIT build: includes compiling what this run had not run before", RenderJob.RenderTimeNote(null, jit: true));
        Assert.Equal("; after a 12.3 ms warm-up render", RenderJob.RenderTimeNote(12.34, jit: true));
    }

    [Fact]
    public void The_native_build_compiles_nothing_so_its_time_needs_no_note_unless_it_warmed_up()
    {
        Assert.Equal("", RenderJob.RenderTimeNote(null, jit: false));
        Assert.Equal("; after a 5.0 ms warm-up render", RenderJob.RenderTimeNote(5, jit: false));
    }
}
