using RayLab.Launcher;

namespace RayLab.Cli.Tests;

/// <summary>
/// The native build's launcher (samples/RayLab.Launcher): the x86-64 level it reads from CPUID's bits, the order in
/// which it tries the console builds beside it, and its message when none starts. <c>execv</c> itself is replaced by a
/// recorder here; the package tests start the installed tool for real.
/// </summary>
public sealed class NativeLauncherTests
{
    // CPUID leaf 1 ECX: FMA 12, MOVBE 22, OSXSAVE 27, AVX 28; leaf 7 EBX: BMI1 3, AVX2 5, BMI2 8.
    private const int V3Ecx1 = (1 << 12) | (1 << 22) | (1 << 27) | (1 << 28);
    private const int V3Ebx7 = (1 << 3) | (1 << 5) | (1 << 8);

    // Leaf 7 EBX: AVX-512 F 16, DQ 17, CD 28, BW 30, VL 31.
    private const int V4Ebx7 = V3Ebx7 | (1 << 16) | (1 << 17) | (1 << 28) | (1 << 30) | (1 << 31);

    [Theory]
    [InlineData(0, 0, 2)]
    [InlineData(V3Ecx1, V3Ebx7, 3)]
    [InlineData(V3Ecx1, V4Ebx7, 4)]
    [InlineData(V3Ecx1 & ~(1 << 27), V4Ebx7, 2)]          // AVX without OSXSAVE: the OS does not save the registers
    [InlineData(V3Ecx1, V3Ebx7 & ~(1 << 5), 2)]            // no AVX2
    [InlineData(V3Ecx1, V4Ebx7 & ~(1 << 31), 3)]           // AVX-512 without VL is not x86-64-v4
    [InlineData(0, V4Ebx7, 2)]                             // AVX-512 bits without the v3 set
    public void The_level_comes_from_cpuid_leaf_1_and_7(int ecx1, int ebx7, int expected) =>
        Assert.Equal(expected, NativeLauncher.Level(ecx1, ebx7));

    [Fact]
    public void It_tries_the_widest_build_the_cpu_runs_first_then_each_narrower_one_that_is_there()
    {
        using var folder = new TempDirectory();
        File.WriteAllText(folder.File("raylab-x86-64-v4"), "");
        File.WriteAllText(folder.File("raylab-x86-64-v2"), "");
        var started = new List<(string Build, string[] Args)>();
        var error = new StringWriter();

        int exit = NativeLauncher.Launch(folder.Path, 4, widest: true, ["render", "a b"], (build, args) =>
        {
            started.Add((build, args));
            return "Permission denied";
        }, error);

        Assert.Equal(NativeLauncher.NotStartedExitCode, exit);
        Assert.Equal([folder.File("raylab-x86-64-v4"), folder.File("raylab-x86-64-v2")], started.Select(s => s.Build));
        Assert.All(started, s => Assert.Equal(["render", "a b"], s.Args));
        Assert.Contains($"{folder.File("raylab-x86-64-v3")}: missing", error.ToString(), StringComparison.Ordinal);
        Assert.Contains($"{folder.File("raylab-x86-64-v4")}: Permission denied", error.ToString(), StringComparison.Ordinal);
    }

    [Fact]
    public void With_no_build_beside_it_it_names_each_missing_build_and_the_cpu_level_and_exits_127()
    {
        using var folder = new TempDirectory();
        var error = new StringWriter();

        int exit = NativeLauncher.Launch(folder.Path, 3, widest: true, [], (_, _) => throw new Xunit.Sdk.XunitException("no build to start"), error);

        Assert.Equal(127, exit);
        string message = error.ToString();
        Assert.StartsWith("raylab: no console build could be started; this CPU is x86-64-v3. Tried:", message, StringComparison.Ordinal);
        Assert.Contains($"{folder.File("raylab-x86-64-v3")}: missing", message, StringComparison.Ordinal);
        Assert.Contains($"{folder.File("raylab-x86-64-v2")}: missing", message, StringComparison.Ordinal);
        Assert.DoesNotContain("raylab-x86-64-v4", message, StringComparison.Ordinal);
    }

    [Fact]
    public void With_the_dispatch_off_it_tries_the_x86_64_v2_build_alone_and_says_why()
    {
        using var folder = new TempDirectory();
        foreach (string build in new[] { "raylab-x86-64-v2", "raylab-x86-64-v3", "raylab-x86-64-v4" })
        {
            File.WriteAllText(folder.File(build), "");
        }

        var started = new List<string>();
        var error = new StringWriter();
        int exit = NativeLauncher.Launch(folder.Path, 4, widest: false, ["scenes"], (build, _) =>
        {
            started.Add(build);
            return "Exec format error";
        }, error);

        Assert.Equal(NativeLauncher.NotStartedExitCode, exit);
        Assert.Equal([folder.File("raylab-x86-64-v2")], started);
        Assert.Contains("this CPU is x86-64-v4 (RAYLAB_NO_DISPATCH is set: the x86-64-v2 build only)", error.ToString(), StringComparison.Ordinal);
    }
}
