using System.Runtime.InteropServices;
using System.Runtime.Intrinsics.X86;
using System.Runtime.Versioning;

namespace RayLab.Launcher;

/// <summary>
/// The native <c>raylab</c> for x64 Linux. Native AOT compiles the AVX2 and AVX-512 checks to constants of the
/// instruction set it targets, so one console binary cannot both run on an SSE-only CPU and take AVX2 where there is
/// AVX2: the console is published once per x86-64 level, as <c>raylab-x86-64-v2</c> (SSE4.2), <c>raylab-x86-64-v3</c>
/// (AVX2, FMA) and <c>raylab-x86-64-v4</c> (AVX-512), and this launcher, published as <c>raylab</c> beside them, asks
/// the CPU its level (CPUID) and replaces itself (<c>execv</c>: same process, same arguments) with the widest build the
/// CPU runs. A build that is missing or cannot be started is passed over for the next narrower one; when none starts,
/// it names each build it looked for, why it did not start, and the CPU's level, and exits with
/// <see cref="NotStartedExitCode"/>.
/// </summary>
internal static partial class NativeLauncher
{
    /// <summary>Set to any value to start the x86-64-v2 build whatever the CPU (for measurements and tests).</summary>
    internal const string DisableVariable = "RAYLAB_NO_DISPATCH";

    /// <summary>The exit code when no build could be started: 127, as a shell reports a command it cannot find.</summary>
    internal const int NotStartedExitCode = 127;

    /// <summary>The narrowest level there is a build for.</summary>
    internal const int LowestLevel = 2;

    private static int Main(string[] args)
    {
        if (!OperatingSystem.IsLinux() && !OperatingSystem.IsMacOS())
        {
            Console.Error.WriteLine("raylab: the native launcher runs on Linux and macOS only; start the console build directly.");
            return NotStartedExitCode;
        }

        int cpu = X86Base.X64.IsSupported ? CpuLevel() : LowestLevel;
        bool widest = Environment.GetEnvironmentVariable(DisableVariable) is null;
        return Launch(AppContext.BaseDirectory, cpu, widest, args, Exec, Console.Error);
    }

    /// <summary>The file name of the console build for x86-64 level <paramref name="level"/>.</summary>
    internal static string BuildName(int level) => $"raylab-x86-64-v{level}";

    /// <summary>
    /// Starts the widest build in <paramref name="folder"/> that the CPU runs, trying narrower ones after a build that is
    /// missing or fails to start; returns only when none started, after saying why on <paramref name="error"/>.
    /// </summary>
    /// <param name="folder">The folder of the builds (the launcher's own).</param>
    /// <param name="cpuLevel">The CPU's x86-64 level, 2 to 4.</param>
    /// <param name="widest">False to try the x86-64-v2 build alone (<see cref="DisableVariable"/> set).</param>
    /// <param name="args">The command line, passed on unchanged.</param>
    /// <param name="exec">Replaces the process with a build; returns only when it could not, with the reason.</param>
    /// <param name="error">Where the failure is written.</param>
    /// <returns><see cref="NotStartedExitCode"/>.</returns>
    internal static int Launch(string folder, int cpuLevel, bool widest, string[] args, Func<string, string[], string> exec, TextWriter error)
    {
        var tried = new List<string>();
        for (int level = widest ? cpuLevel : LowestLevel; level >= LowestLevel; level--)
        {
            string build = Path.Combine(folder, BuildName(level));
            tried.Add($"  {build}: {(File.Exists(build) ? exec(build, args) : "missing")}");
        }

        error.WriteLine($"raylab: no console build could be started; this CPU is x86-64-v{cpuLevel}"
            + (widest ? "" : $" ({DisableVariable} is set: the x86-64-v2 build only)") + ". Tried:");
        foreach (string line in tried)
        {
            error.WriteLine(line);
        }

        error.WriteLine("Reinstall the tool (dotnet tool update RayLab.Tool), or publish the builds again (tools/publish-native.sh).");
        return NotStartedExitCode;
    }

    /// <summary>The x86-64 level (2, 3 or 4) of CPUID leaf 1's ECX and leaf 7's EBX.</summary>
    /// <param name="ecx1">ECX of CPUID leaf 1.</param>
    /// <param name="ebx7">EBX of CPUID leaf 7, subleaf 0.</param>
    internal static int Level(int ecx1, int ebx7)
    {
        static bool Bit(int register, int bit) => (register & (1 << bit)) != 0;

        // v3: AVX (with the OS saving its registers: OSXSAVE), FMA, MOVBE, AVX2, BMI1, BMI2 (LZCNT aside).
        bool v3 = Bit(ecx1, 28) && Bit(ecx1, 27) && Bit(ecx1, 12) && Bit(ecx1, 22) && Bit(ebx7, 5) && Bit(ebx7, 3) && Bit(ebx7, 8);
        // v4: AVX-512 F, DQ, CD, BW, VL.
        bool v4 = v3 && Bit(ebx7, 16) && Bit(ebx7, 17) && Bit(ebx7, 28) && Bit(ebx7, 30) && Bit(ebx7, 31);
        return v4 ? 4 : v3 ? 3 : LowestLevel;
    }

    private static int CpuLevel()
    {
        (_, _, int ecx1, _) = X86Base.CpuId(1, 0);
        (_, int ebx7, _, _) = X86Base.CpuId(7, 0);
        return Level(ecx1, ebx7);
    }

    /// <summary>
    /// <c>execv</c>s <paramref name="path"/>; if that fails, adds the execute bits the file's read bits allow (a package
    /// extractor may not keep them) and tries once more. Returns only on failure, with the system's reason.
    /// </summary>
    [UnsupportedOSPlatform("windows")]
    private static string Exec(string path, string[] args)
    {
        int errno = ExecOnce(path, args);
        if (AllowExecute(path))
        {
            errno = ExecOnce(path, args);
        }

        return Marshal.GetPInvokeErrorMessage(errno);
    }

    /// <summary>
    /// Adds execute permission wherever the file grants read permission (u+x for its owner, and g+x, o+x as its read
    /// bits allow); false when nothing changed or it is not ours.
    /// </summary>
    [UnsupportedOSPlatform("windows")]
    private static bool AllowExecute(string path)
    {
        try
        {
            UnixFileMode mode = File.GetUnixFileMode(path);
            UnixFileMode wanted = mode
                | (mode.HasFlag(UnixFileMode.UserRead) ? UnixFileMode.UserExecute : 0)
                | (mode.HasFlag(UnixFileMode.GroupRead) ? UnixFileMode.GroupExecute : 0)
                | (mode.HasFlag(UnixFileMode.OtherRead) ? UnixFileMode.OtherExecute : 0);
            if (wanted == mode)
            {
                return false; // already executable: execv failed for another reason
            }

            File.SetUnixFileMode(path, wanted);
            return true;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return false;
        }
    }

    /// <summary>One <c>execv</c>; returns only when it failed, with its errno.</summary>
    private static unsafe int ExecOnce(string path, string[] args)
    {
        var argv = new nint[args.Length + 2];
        try
        {
            argv[0] = Marshal.StringToCoTaskMemUTF8(path);
            for (int i = 0; i < args.Length; i++)
            {
                argv[i + 1] = Marshal.StringToCoTaskMemUTF8(args[i]);
            }

            fixed (nint* pointers = argv)
            {
                _ = ExecV((byte*)argv[0], pointers);
                return Marshal.GetLastPInvokeError();
            }
        }
        finally
        {
            foreach (nint p in argv)
            {
                Marshal.FreeCoTaskMem(p);
            }
        }
    }

    [LibraryImport("libc", EntryPoint = "execv", SetLastError = true)]
    private static unsafe partial int ExecV(byte* path, nint* argv);
}
