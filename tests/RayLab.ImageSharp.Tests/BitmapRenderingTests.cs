using RayLab.Sampling;
using SixLabors.ImageSharp;
using Bitmap = SixLabors.ImageSharp.Image<SixLabors.ImageSharp.PixelFormats.Rgb24>;

namespace RayLab.ImageSharp.Tests;

/// <summary>Rendering into an ImageSharp <c>Image&lt;Rgb24&gt;</c>: the bytes of a render into RayLab's <see cref="Image"/>, for every method and thread count.</summary>
public class BitmapRenderingTests
{
    public static TheoryData<string, int> MethodsAndThreads()
    {
        var data = new TheoryData<string, int>();
        foreach (string name in TwoSpheres.MethodNames)
        {
            data.Add(name, 1);
            data.Add(name, 2);
            data.Add(name, -1);
        }

        return data;
    }

    /// <summary>Every pixel of a bitmap as bytes R, G, B, row 0 first.</summary>
    internal static byte[] Bytes(Bitmap bitmap)
    {
        var bytes = new byte[bitmap.Width * bitmap.Height * 3];
        bitmap.CopyPixelDataTo(bytes);
        return bytes;
    }

    [Theory]
    [MemberData(nameof(MethodsAndThreads))]
    public void A_render_into_the_bitmap_has_the_bytes_and_rays_of_a_render_into_an_Image(string name, int threads)
    {
        const int w = 83, h = 47;
        foreach (Camera camera in new[] { TwoSpheres.Perspective, TwoSpheres.Orthographic })
        {
            var image = new Image(w, h);
            var imageRays = new float[w * h];
            RenderStatistics expected = new Renderer { MaxDegreeOfParallelism = 1 }.Render(TwoSpheres.Scene, camera, TwoSpheres.Method(name), image, imageRays);

            using var bitmap = new Bitmap(w, h);
            var bitmapRays = new float[w * h];
            RenderStatistics actual = new Renderer { MaxDegreeOfParallelism = threads }.Render(TwoSpheres.Scene, camera, TwoSpheres.Method(name), bitmap, bitmapRays);

            Assert.Equal(image.PixelBytes.ToArray(), Bytes(bitmap));
            Assert.Equal(imageRays, bitmapRays);
            Assert.Equal(expected.PrimaryRays, actual.PrimaryRays);
            Assert.NotEqual(new byte[w * h * 3], Bytes(bitmap)); // not a black picture that equals a black picture
        }
    }

    [Fact]
    public void The_sampler_and_adaptive_overloads_and_RenderRows_give_the_same_bytes()
    {
        const int w = 64, h = 48;
        var jittered = new RayLab.Sampling.JitteredSampler(9, seed: 3);
        var adaptive = new AdaptiveSampler(0, 3, 0.05);

        var image = new Image(w, h);
        new Renderer().Render(TwoSpheres.Scene, TwoSpheres.Perspective, jittered, image);
        using var bitmap = new Bitmap(w, h);
        new Renderer().Render(TwoSpheres.Scene, TwoSpheres.Perspective, jittered, bitmap);
        Assert.Equal(image.PixelBytes.ToArray(), Bytes(bitmap));

        new Renderer().Render(TwoSpheres.Scene, TwoSpheres.Perspective, adaptive, image);
        new Renderer().Render(TwoSpheres.Scene, TwoSpheres.Perspective, adaptive, bitmap);
        Assert.Equal(image.PixelBytes.ToArray(), Bytes(bitmap));

        using var banded = new Bitmap(w, h);
        var renderer = new Renderer { MaxDegreeOfParallelism = 1 };
        foreach ((int first, int count) in new[] { (0, 10), (10, 1), (11, 37) })
        {
            renderer.RenderRows(TwoSpheres.Scene, TwoSpheres.Perspective, RenderMethod.Adaptive(adaptive), banded, first, count);
        }

        Assert.Equal(image.PixelBytes.ToArray(), Bytes(banded));
    }

    [Fact]
    public void A_frame_that_spans_several_ImageSharp_buffers_is_written_row_by_row_in_place()
    {
        // ImageSharp 2.1 keeps a large frame in several buffers (each row contiguous): 1600×1200×3 bytes is 5.8 MB.
        const int w = 1600, h = 1200;
        using var bitmap = new Bitmap(w, h);
        Assert.False(bitmap.DangerousTryGetSinglePixelMemory(out _), "the frame fits one buffer; the test needs one that does not");
        new Renderer().Render(TwoSpheres.Scene, TwoSpheres.Perspective, RenderMethod.Exact, bitmap);

        var image = new Image(w, h);
        new Renderer().Render(TwoSpheres.Scene, TwoSpheres.Perspective, RenderMethod.Exact, image);
        Assert.Equal(image.PixelBytes.ToArray(), Bytes(bitmap));
    }

    [Fact]
    public void Progress_counts_every_row_of_the_bitmap()
    {
        var progress = new RenderProgress();
        using var bitmap = new Bitmap(40, 30);
        new Renderer { Progress = progress }.Render(TwoSpheres.Scene, TwoSpheres.Perspective, TwoSpheres.Method("jittered"), bitmap);
        Assert.Equal(30, progress.TotalRows);
        Assert.Equal(30, progress.RowsCompleted);
    }

    [Fact]
    public void A_cancelled_render_throws_before_the_student_saves_and_leaves_no_file()
    {
        string folder = Directory.CreateTempSubdirectory("raylab-imagesharp-").FullName;
        try
        {
            string path = Path.Combine(folder, "obrazkoncowy.jpg");
            using var cancel = new CancellationTokenSource();
            // Cancelled from inside the render, at the tenth pixel the method is asked for: the render stops part-way.
            var method = RenderMethod.Custom(new CancelAt(cancel, 10));
            using var bitmap = new Bitmap(64, 48);
            var renderer = new Renderer { CancellationToken = cancel.Token, MaxDegreeOfParallelism = 1 };

            Assert.Throws<OperationCanceledException>(() =>
            {
                renderer.Render(TwoSpheres.Scene, TwoSpheres.Perspective, method, bitmap);
                bitmap.SaveAsJpeg(path); // the lab's snippet: never reached
            });
            Assert.False(File.Exists(path));
            Assert.Empty(Directory.GetFiles(folder));
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    [Fact]
    public void Null_arguments_are_named()
    {
        using var bitmap = new Bitmap(4, 4);
        Assert.Equal("bitmap", Assert.Throws<ArgumentNullException>(() => new Renderer().Render(TwoSpheres.Scene, TwoSpheres.Perspective, RenderMethod.Exact, (Bitmap)null!)).ParamName);
        Assert.Equal("renderer", Assert.Throws<ArgumentNullException>(() => ((Renderer)null!).Render(TwoSpheres.Scene, TwoSpheres.Perspective, RenderMethod.Exact, bitmap)).ParamName);
        Assert.Throws<ArgumentOutOfRangeException>(() => new Renderer().RenderRows(TwoSpheres.Scene, TwoSpheres.Perspective, RenderMethod.Exact, bitmap, 2, 3));
    }

    private sealed class CancelAt(CancellationTokenSource cancel, int pixels) : IPixelMethod<int>
    {
        private int _seen;

        public string Name => "cancel-at";

        public int CreateScratch() => 0;

        public Intensity RenderPixel(PixelTracer pixel, ref int scratch)
        {
            if (Interlocked.Increment(ref _seen) == pixels)
            {
                cancel.Cancel();
            }

            return pixel.Trace(0.5, 0.5);
        }
    }
}
