using FsCheck;
using FsCheck.Fluent;
using Microsoft.FSharp.Core;

namespace RayLab.Tests.Shared;

/// <summary>
/// FsCheck with a fixed replay seed, so every run (and CI) tries the same cases: a failure is reproducible
/// from the test alone. No shrinking: the generators build values that print readably as they are.
/// </summary>
internal static class PropertyCheck
{
    /// <summary>The replay seed all property tests share.</summary>
    public const ulong Seed = 20_261_122;

    /// <summary>Runs <paramref name="property"/> (it asserts; a throw fails the check) on <paramref name="tests"/> generated values.</summary>
    public static void ForAll<T>(Gen<T> gen, int tests, Action<T> property, ulong seed = Seed)
    {
        Config config = Config.QuickThrowOnFailure
            .WithMaxTest(tests)
            .WithQuietOnSuccess(true)
            .WithReplay(FSharpOption<Replay>.Some(new Replay(new Rnd(seed), FSharpOption<int>.None)));
        Check.One(config, Prop.ForAll(gen.ToArbitrary(), property));
    }

    /// <summary>A double uniform in [0, 1) with all 53 bits random.</summary>
    public static Gen<double> Unit { get; } =
        Gen.Choose(0, (1 << 26) - 1).SelectMany(hi => Gen.Choose(0, (1 << 27) - 1), (hi, lo) => ((hi * (double)(1 << 27)) + lo) / (1L << 53));

    /// <summary>A double uniform in [−1, 1).</summary>
    public static Gen<double> Signed { get; } = Unit.Select(u => (2 * u) - 1);

    /// <summary>A double uniform in [lo, hi).</summary>
    public static Gen<double> Between(double lo, double hi) => Unit.Select(u => lo + ((hi - lo) * u));

    /// <summary>2^e for an integer e in [lo, hi].</summary>
    public static Gen<double> PowerOfTwo(int lo, int hi) => Gen.Choose(lo, hi).Select(e => Math.ScaleB(1.0, e));
}
