
namespace RayLab.Cli.Tests;

/// <summary><c>raylab chart TABLE.csv --out STEM</c> (hidden): the helper behind docs/sphere-count.png.</summary>
public sealed class ChartCliTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("raylab-chart-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private static (int Code, string Out, string Err) Run(params string[] args) => ConsoleRunner.Run(args);

    [Fact]
    public void ATableBecomesAPngAndAnSvgWithCutOffCellsLeftOut()
    {
        string table = Path.Combine(_dir, "t.csv"), stem = Path.Combine(_dir, "chart");
        File.WriteAllText(table, "spheres,fast,slow\n1,2.5,3\n10,4,> 60 s\n100,8.5,\n");

        var r = Run("chart", table, "--out", stem, "--title", "cost", "--y-label", "ms");

        Assert.True(r.Code == 0, r.Err);
        Assert.Equal($"{stem}.png, {stem}.svg: 2 lines, 4 points", r.Out.TrimEnd());
        SkiaDecode.Result png = SkiaDecode.Load(stem + ".png");
        Assert.Equal((900, 540), (png.Width, png.Height));
        Assert.Contains("<svg", File.ReadAllText(stem + ".svg"), StringComparison.Ordinal);
    }

    [Fact]
    public void ARowWithTheWrongNumberOfCellsIsAOneLineErrorNamingTheLine()
    {
        string table = Path.Combine(_dir, "bad.csv");
        File.WriteAllText(table, "spheres,fast\n1,2\n10\n");

        var r = Run("chart", table, "--out", Path.Combine(_dir, "c"));

        Assert.Equal(1, r.Code);
        Assert.Equal($"raylab: error: {table}: line 3: 1 cells, the header has 2", r.Err.TrimEnd());
        Assert.Empty(Directory.GetFiles(_dir, "c.*"));
    }

    [Fact]
    public void TheHelperIsHiddenFromTheHelp()
    {
        var r = Run("--help");
        Assert.Equal(0, r.Code);
        Assert.Contains("\n  scenes", r.Out, StringComparison.Ordinal);
        Assert.DoesNotContain("\n  chart", r.Out, StringComparison.Ordinal);
    }
}
