
namespace RayLab.Tests.Shared;

/// <summary>Deterministic test images whose rows make the PNG encoder choose every filter type.</summary>
internal static class TestImages
{
    /// <summary>The number of rows in the repeating pattern of <see cref="Varied"/>.</summary>
    public const int BandHeight = 9;

    /// <summary>
    /// An image built from a 9-row pattern, filled from a seeded <see cref="Random"/> and gradients. Rows 1, 3, 4,
    /// 6 and 8 of each band are built so that one filter has a strictly smaller sum of absolute values than the
    /// other four (for images about 16 pixels wide and more), whatever the tie-breaking:
    /// <list type="number">
    /// <item>row 0: random bytes;</item>
    /// <item>row 1: a horizontal gradient under random bytes — Sub;</item>
    /// <item>row 2: the constant 128;</item>
    /// <item>row 3: 128 plus small random offsets in −8..8 under the flat row — Up;</item>
    /// <item>row 4: bytes alternating 8 and 248 (±8) under the noisy row — None;</item>
    /// <item>row 5: random bytes;</item>
    /// <item>row 6: each byte the floor of the mean of its left neighbour and the byte above — Average;</item>
    /// <item>row 7: left half random, right half the constant 20;</item>
    /// <item>row 8: left half a copy of the row above, right half the constant 220 — Paeth.</item>
    /// </list>
    /// </summary>
    public static Image Varied(int width, int height, int seed)
    {
        var image = new Image(width, height);
        var random = new Random(seed);
        Span<byte> pixels = image.PixelBytes;
        int rowBytes = width * 3;
        int half = width / 2 * 3;
        for (int y = 0; y < height; y++)
        {
            Span<byte> row = pixels.Slice(y * rowBytes, rowBytes);
            ReadOnlySpan<byte> up = y > 0 ? pixels.Slice((y - 1) * rowBytes, rowBytes) : new byte[rowBytes];
            switch (y % BandHeight)
            {
                case 0:
                case 5:
                    random.NextBytes(row);
                    break;
                case 1:
                    for (int i = 0; i < rowBytes; i++)
                    {
                        row[i] = (byte)((i / 3 * 5) + (i % 3 * 60) + y);
                    }

                    break;
                case 2:
                    row.Fill(128);
                    break;
                case 3:
                    for (int i = 0; i < rowBytes; i++)
                    {
                        row[i] = (byte)(128 + random.Next(-8, 9));
                    }

                    break;
                case 4:
                    for (int i = 0; i < rowBytes; i++)
                    {
                        row[i] = i % 2 == 0 ? (byte)8 : (byte)248;
                    }

                    break;
                case 6:
                    for (int i = 0; i < rowBytes; i++)
                    {
                        int left = i >= 3 ? row[i - 3] : 0;
                        row[i] = (byte)((left + up[i]) >> 1);
                    }

                    break;
                case 7:
                    random.NextBytes(row[..half]);
                    row[half..].Fill(20);
                    break;
                default:
                    up[..half].CopyTo(row);
                    row[half..].Fill(220);
                    break;
            }
        }

        return image;
    }

    /// <summary>An image of pure noise from a seeded generator.</summary>
    public static Image Noise(int width, int height, int seed)
    {
        var image = new Image(width, height);
        new Random(seed).NextBytes(image.PixelBytes);
        return image;
    }
}
