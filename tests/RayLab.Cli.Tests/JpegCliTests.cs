
namespace RayLab.Cli.Tests;

/// <summary><c>raylab render … -o obrazkoncowy.jpg</c>: the file name of the lab's own snippet.</summary>
public sealed class JpegCliTests : IDisposable
{
    private readonly TempDirectory _dir = new();

    public void Dispose() => _dir.Dispose();

    private static string LabScene => Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json");

    private static void Render(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = Program.Run(["render", LabScene, .. args], stdout, stderr);
        Assert.True(code == 0, stderr.ToString());
        Assert.Equal("", stderr.ToString());
    }

    [Fact]
    public void TheLabsJpegDecodesToWithinAFewLevelsOfThePng()
    {
        string jpg = _dir.File("obrazkoncowy.jpg"), png = _dir.File("obrazkoncowy.png"), webp = _dir.File("obrazkoncowy.webp");

        Render("-o", jpg);
        Render("-o", png);
        Render("-o", webp);

        SkiaDecode.Result lossless = SkiaDecode.Load(png);
        var report = new List<string>();
        bool within = true;
        foreach (string file in new[] { jpg, webp })
        {
            SkiaDecode.Result lossy = SkiaDecode.Load(file);
            Assert.Equal((lossless.Width, lossless.Height), (lossy.Width, lossy.Height));
            int[] diff = [.. lossless.Rgb.Zip(lossy.Rgb, (a, b) => Math.Abs(a - b)).Order()];
            double mean = diff.Average();
            int p99 = diff[(int)(diff.Length * 0.99)];
            // Off by a level or less on average and by a few at the 99th percentile; only along the spheres'
            // outlines, where a sharp edge rings, is a channel off by more.
            within &= mean <= 1 && p99 <= 8;
            report.Add($"{Path.GetFileName(file)}: mean |difference| {mean:F3} levels, 99th percentile {p99}, 99.9th {diff[(int)(diff.Length * 0.999)]}, max {diff[^1]}");
        }

        Assert.True(within, string.Join("; ", report));

        Assert.True(new FileInfo(jpg).Length < new FileInfo(png).Length * 4, "a JPEG of a flat-shaded render is not bloated");
    }

    [Fact]
    public void AQualityOfOneHundredIsCloserThanTheDefault()
    {
        string fine = _dir.File("fine.jpg"), standard = _dir.File("standard.jpg"), png = _dir.File("ref.png");

        Render("-o", fine, "--quality", "100", "--width", "200", "--height", "150");
        Render("-o", standard, "--width", "200", "--height", "150");
        Render("-o", png, "--width", "200", "--height", "150");

        byte[] reference = SkiaDecode.Load(png).Rgb;
        double Error(string file) => reference.Zip(SkiaDecode.Load(file).Rgb, (a, b) => Math.Abs(a - b)).Average();
        Assert.True(Error(fine) < Error(standard), $"quality 100: {Error(fine):F3}, default: {Error(standard):F3}");
        Assert.True(new FileInfo(fine).Length > new FileInfo(standard).Length);
    }
}
