using BenchmarkDotNet.Running;

namespace RayLab.Benchmarks;

/// <summary>
/// RayLab's benchmarks (BenchmarkDotNet): <c>dotnet run -c Release --project benchmarks/RayLab.Benchmarks -- --filter '*'</c>,
/// or one class, e.g. <c>--filter '*Frame*'</c>. <c>-- png-sizes</c> prints the PNG size table (and Skia's sizes) instead,
/// <c>-- jpeg-sizes</c> the JPEG encoders' sizes and errors, <c>-- jpeg-first CANDIDATE PICTURE</c> one first-call time.
/// </summary>
public static class Program
{
    public static int Main(string[] args)
    {
        if (args is ["png-sizes"])
        {
            PngSizes.Print(Console.Out);
            Console.Out.WriteLine();
            SkiaSizes.Print(Console.Out);
            Console.Out.WriteLine();
            ZlibLevels.Print(Console.Out);
            return 0;
        }

        if (args is ["jpeg-sizes"])
        {
            JpegSizes.Print(Console.Out);
            return 0;
        }

        if (args is ["jpeg-first", string candidate, string picture])
        {
            JpegSizes.PrintFirst(Console.Out, candidate, picture);
            return 0;
        }

        BenchmarkSwitcher.FromAssembly(typeof(Program).Assembly).Run(args);
        return 0;
    }
}
