using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics.X86;
using System.Runtime.Versioning;

namespace RayLab.Cli;

/// <summary>
/// The native build's choice of SIMD width at run time. Native AOT compiles AVX2 and AVX-512 checks to constants of
/// the instruction set it was published for, so one binary cannot both run on an SSE-only CPU and take AVX2 where
/// there is AVX2. <c>tools/publish-native.sh</c> therefore publishes an x86-64-v2 <c>raylab</c> (runs on any
/// x64 of the last 15 years) with <c>raylab-x86-64-v3</c> (AVX2, FMA) and <c>raylab-x86-64-v4</c> (AVX-512) beside
/// it; at start-up <c>raylab</c> asks the CPU (CPUID) and replaces itself (<c>execv</c>, same process id, same
/// arguments) with the widest of those its CPU runs. The .NET tool's native package <c>RayLab.Tool.linux-x64</c> has
/// the same layout (<c>dotnet pack -r linux-x64</c>). A binary published alone never finds a sibling and just runs.
/// A sibling that cannot be started (no execute permission that this user can add, a file system mounted noexec) is
/// passed over for the next narrower one, down to this binary itself: slower, never failing; <c>--stats</c> then
/// names the kernel that ran.
/// </summary>
internal static partial class NativeDispatch
{
    /// <summary>Set to any value to stay in the binary that was started (for measurements and tests).</summary>
    public const string DisableVariable = "RAYLAB_NO_DISPATCH";

    /// <summary>Replaces the process with a wider sibling build when there is one this CPU runs; returns otherwise.</summary>
    /// <param name="args">The command-line arguments, passed on unchanged.</param>
    public static void ExecWidest(string[] args)
    {
        if (RuntimeFeature.IsDynamicCodeSupported || !X86Base.X64.IsSupported || !(OperatingSystem.IsLinux() || OperatingSystem.IsMacOS())
            || Environment.GetEnvironmentVariable(DisableVariable) is not null)
        {
            return;
        }

        // The level this binary was compiled for: these IsSupported checks are constants in a native build.
        int own = Avx512F.IsSupported ? 4 : Avx2.IsSupported ? 3 : 2;
        for (int level = CpuLevel(); level > own; level--)
        {
            string sibling = Path.Combine(AppContext.BaseDirectory, $"raylab-x86-64-v{level}");
            if (File.Exists(sibling))
            {
                Exec(sibling, args); // returns only if execv failed
                if (AllowExecute(sibling))
                {
                    Exec(sibling, args);
                }

                // Still here: that build cannot be started; the next narrower one, or this binary itself, runs the command.
            }
        }
    }

    /// <summary>The x86-64 microarchitecture level the CPU reports (2, 3 or 4), from CPUID leaves 1 and 7.</summary>
    private static int CpuLevel()
    {
        (_, _, int ecx1, _) = X86Base.CpuId(1, 0);
        (_, int ebx7, _, _) = X86Base.CpuId(7, 0);
        static bool Bit(int register, int bit) => (register & (1 << bit)) != 0;

        // v3: AVX (with the OS saving its registers: OSXSAVE), FMA, MOVBE, AVX2, BMI1, BMI2 (LZCNT aside).
        bool v3 = Bit(ecx1, 28) && Bit(ecx1, 27) && Bit(ecx1, 12) && Bit(ecx1, 22) && Bit(ebx7, 5) && Bit(ebx7, 3) && Bit(ebx7, 8);
        // v4: AVX-512 F, DQ, CD, BW, VL.
        bool v4 = v3 && Bit(ebx7, 16) && Bit(ebx7, 17) && Bit(ebx7, 28) && Bit(ebx7, 30) && Bit(ebx7, 31);
        return v4 ? 4 : v3 ? 3 : 2;
    }

    /// <summary>
    /// Adds execute permission wherever the file grants read permission (u+x for its owner, and g+x, o+x as its read
    /// bits allow), for a package extractor that did not keep the bits; false when nothing changed or it is not ours.
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

    private static unsafe void Exec(string path, string[] args)
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

    [LibraryImport("libc", EntryPoint = "execv")]
    private static unsafe partial int ExecV(byte* path, nint* argv);
}
