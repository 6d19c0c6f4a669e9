using System.Runtime.CompilerServices;

namespace RayLab.Rendering.Exact;

/// <summary>
/// The exact row cut strip by strip: between two neighbouring cuts each present outline has a left and a right
/// branch that meet neither another branch nor a pixel edge, so the branches split the strip into pieces of one
/// colour, each found with one ray through its middle. The reference the sweep (<see cref="RowSweep"/>) must match
/// to the byte, and the row's algorithm where the sweep does not pay or cannot be trusted (<see cref="ExactRow"/>).
/// </summary>
internal sealed class StripCutter(Outline[] outlines, int width, RowBranches branches, PixelRays rays, RowPixels pixels)
{
    /// <summary>Adds every strip between neighbouring <paramref name="cuts"/> (sorted) to the row's pixels.</summary>
    /// <param name="cuts">The row's cuts, sorted, its top and bottom included.</param>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    public void Cut(List<double> cuts)
    {
        for (int k = 0; k + 1 < cuts.Count; k++)
        {
            if (cuts[k + 1] > cuts[k])
            {
                Strip(cuts[k], cuts[k + 1]);
            }
        }
    }

    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void Strip(double ya, double yb)
    {
        double ym = 0.5 * (ya + yb), h = yb - ya;
        Span<Branch> at = branches.At(ym);
        int n = at.Length;

        // Walk the pieces left to right; a branch outside the image stands for the image's edge.
        double leftX = 0, leftIntegral = 0;
        for (int k = 0; k <= n; k++)
        {
            double rightX = width, rightIntegral = width * h;
            if (k < n)
            {
                Branch branch = at[k];
                if (branch.X <= 0)
                {
                    continue;
                }

                if (branch.X < width)
                {
                    rightX = branch.X;
                    rightIntegral = outlines[branch.Outline].Integral(branch.Sign, ya, yb);
                }
            }

            if (rightX > leftX)
            {
                pixels.Piece(leftX, leftIntegral, rightX, rightIntegral, h, rays.Colour(0.5 * (leftX + rightX), ym));
                leftX = rightX;
                leftIntegral = rightIntegral;
            }

            if (rightX >= width)
            {
                break;
            }
        }
    }
}
