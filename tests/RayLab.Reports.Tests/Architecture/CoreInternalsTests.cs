using ArchUnitNET.Domain;
using ArchUnitNET.Domain.Dependencies;
using ArchUnitNET.Loader;
using RayLab.Reports.Comparison;

namespace RayLab.Reports.Tests.Architecture;

/// <summary>
/// RayLab.Reports sees the core's internals (it ships with, and pins, the same core version), but uses only the
/// few listed here, read from its IL: everything else it draws goes through the core's public API, as a student's
/// code would. A new internal use fails until it is listed, with its reason.
/// </summary>
public sealed class CoreInternalsTests
{
    /// <summary>The core's internal types and members Reports may use, with why.</summary>
    private static readonly Dictionary<string, string> Allowed = new()
    {
        ["RayLab.Image.CheckSize"] = "the core's own size rule, so a heat map rejects the sizes an Image would",
        ["RayLab.Sampling.CounterHash"] = "the samplers' counter hash, so the patterns report's random test functions are reproducible the same way",
        ["RayLab.Metrics.ErrorPlanes"] = "compare makes a picture's error planes once for its two low-pass errors and its spectrum, in pooled arrays",
        ["RayLab.Metrics.ErrorLocation.LowPassRmse"] = "the low-pass error of planes compare has already made",
        ["RayLab.Metrics.ErrorLocation.Spectrum"] = "the error spectrum of planes compare has already made",
    };

    private static readonly Lazy<ArchUnitNET.Domain.Architecture> Both = new(() =>
        new ArchLoader().LoadAssemblies(typeof(CompareRunner).Assembly, typeof(Scene).Assembly).Build());

    [Fact]
    public void Reports_uses_only_the_listed_internals_of_the_core()
    {
        string core = typeof(Scene).Assembly.GetName().Name!;
        string reports = typeof(CompareRunner).Assembly.GetName().Name!;
        var used = new SortedSet<string>(StringComparer.Ordinal);
        foreach (IType type in Both.Value.Types.Where(t => t.Assembly.Name.StartsWith(reports, StringComparison.Ordinal)))
        {
            foreach (ITypeDependency dependency in type.Dependencies)
            {
                IType target = dependency.Target;
                if (!target.Assembly.Name.StartsWith(core, StringComparison.Ordinal))
                {
                    continue;
                }

                if (target.Visibility != Visibility.Public)
                {
                    used.Add(Outer(target.FullName));
                }
                else if (dependency is IMemberMemberDependency { TargetMember: { Visibility: not Visibility.Public } member })
                {
                    used.Add($"{target.FullName}.{member.Name[..member.Name.IndexOf('(', StringComparison.Ordinal)]}");
                }
            }
        }

        Assert.True(used.Count > 0, "the check found no internal use at all (Image.CheckSize at least is one)");
        string[] unlisted = [.. used.Where(u => !Allowed.ContainsKey(u))];
        Assert.True(unlisted.Length == 0, $"RayLab.Reports uses core internals that are not listed: {string.Join(", ", unlisted)}");
        string[] stale = [.. Allowed.Keys.Where(a => !used.Contains(a))];
        Assert.True(stale.Length == 0, $"Listed but no longer used, so take them off: {string.Join(", ", stale)}");
    }

    private static string Outer(string fullName) => fullName.Split('+')[0].Split('<')[0];
}
