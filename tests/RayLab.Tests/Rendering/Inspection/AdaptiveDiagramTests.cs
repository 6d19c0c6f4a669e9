using RayLab.Sampling;
using RayLab.Rendering.Inspection;
using RayLab.Scenes;

namespace RayLab.Tests.Rendering.Inspection;

public class AdaptiveDiagramTests
{
    private static readonly string ScenePath = Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json");

    [Fact]
    public void The_diagram_of_an_edge_pixel_reproduces_the_renderers_pixel_and_its_weights_add_up_to_one()
    {
        PreparedScene scene = SceneFile.Load(ScenePath).Prepare();
        var sampler = new AdaptiveSampler(0, 3, 0.05);
        const int W = 160, H = 120;

        AdaptiveDiagram diagram = AdaptiveDiagram.FindEdgePixel(scene.Scene, scene.Camera, W, H, sampler);

        var image = new Image(W, H);
        new Renderer().Render(scene.Scene, scene.Camera, RenderMethod.Adaptive(sampler), image);
        // Σ weight × value and the nested rule ¼ Σ (c + X)/2 are the same number up to rounding; this pixel's green
        // can land within rounding of a level boundary (0.1 + 0.7·204/512 is exactly 97 levels), so compare within a level.
        Rgb24 rendered = image.GetPixel(diagram.PixelX, diagram.PixelY), drawn = Rgb24.FromIntensity(diagram.Value);
        Assert.InRange(Math.Abs(rendered.R - drawn.R), 0, 1);
        Assert.InRange(Math.Abs(rendered.G - drawn.G), 0, 1);
        Assert.InRange(Math.Abs(rendered.B - drawn.B), 0, 1);
        Assert.True(rendered != Rgb24.FromIntensity(scene.Scene.Background), "the diagram's pixel is an edge pixel");
        Assert.Equal(1, diagram.Points.Sum(p => p.Weight), 1e-12);
        Assert.Equal(["A", "B", "C", "D", "E"], diagram.Points.Take(5).Select(p => p.Label));
        Assert.Equal((0.5, 0.5), (diagram.Points[4].X, diagram.Points[4].Y)); // E, the centre
        Assert.True(diagram.Points.Count > 5, "an edge pixel is subdivided");
        Assert.Contains(diagram.Squares, s => s.Depth >= 2);
        Assert.InRange(Math.Abs(diagram.Value.R - diagram.Exact.R), 0, 0.2);
    }

    [Fact]
    public void Labels_skip_I_and_O_as_the_lab_does()
    {
        Assert.Equal("H", AdaptiveDiagram.Label(7));
        Assert.Equal("J", AdaptiveDiagram.Label(8));
        Assert.Equal("P", AdaptiveDiagram.Label(13));
        Assert.Equal("AA", AdaptiveDiagram.Label(24));
    }
}
