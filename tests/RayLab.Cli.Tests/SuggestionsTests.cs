
namespace RayLab.Cli.Tests;

/// <summary>The edit distance and the nearest-name rule behind "did you mean …?".</summary>
public sealed class SuggestionsTests
{
    [Theory]
    [InlineData("", "", 0)]
    [InlineData("", "abc", 3)]
    [InlineData("abc", "", 3)]
    [InlineData("samples", "samples", 0)]
    [InlineData("kitten", "sitting", 3)]        // the textbook Levenshtein pair: two substitutions and an insertion
    [InlineData("sampels", "samples", 1)]       // one swap of neighbours (plain Levenshtein says 2)
    [InlineData("ab", "ba", 1)]
    [InlineData("ca", "abc", 3)]                // optimal string alignment: no edit of a swapped pair (full Damerau says 2)
    [InlineData("rendr", "render", 1)]
    [InlineData("jitterd", "jittered", 1)]
    [InlineData("Jittered", "jittered", 1)]     // ordinal: case counts here; Nearest ignores it
    public void DistanceCountsInsertionsDeletionsSubstitutionsAndSwaps(string a, string b, int expected)
    {
        Assert.Equal(expected, Suggestions.Distance(a, b));
        Assert.Equal(expected, Suggestions.Distance(b, a));
    }

    // Every word of up to 4 letters over {a, b, c}: 121 words, 14 641 pairs.
    private static readonly string[] Words =
        [.. Enumerable.Range(0, 5).SelectMany(n => Enumerable.Range(0, (int)Math.Pow(3, n))
            .Select(k => new string([.. Enumerable.Range(0, n).Select(i => "abc"[k / (int)Math.Pow(3, i) % 3])])))];

    [Fact]
    public void OneEditOfAnyKindIsDistanceOne()
    {
        foreach (string w in Words)
        {
            var edits = new List<string>();
            for (int i = 0; i <= w.Length; i++)
            {
                edits.AddRange("abc".Select(c => w.Insert(i, c.ToString())));
                if (i < w.Length)
                {
                    edits.Add(w.Remove(i, 1));
                    edits.AddRange("abc".Where(c => c != w[i]).Select(c => w.Remove(i, 1).Insert(i, c.ToString())));
                }

                if (i + 1 < w.Length && w[i] != w[i + 1])
                {
                    edits.Add(string.Concat(w[..i], w[i + 1].ToString(), w[i].ToString(), w[(i + 2)..]));
                }
            }

            Assert.All(edits, e => Assert.True(Suggestions.Distance(w, e) == 1, $"'{w}' → '{e}': {Suggestions.Distance(w, e)}"));
        }
    }

    [Fact]
    public void DistanceIsSymmetricZeroOnlyForEqualWordsAndBoundedByTheLengths()
    {
        foreach (string a in Words)
        {
            foreach (string b in Words)
            {
                int d = Suggestions.Distance(a, b);
                Assert.Equal(d, Suggestions.Distance(b, a));
                Assert.Equal(a == b, d == 0);
                Assert.InRange(d, Math.Abs(a.Length - b.Length), Math.Max(a.Length, b.Length));
            }
        }
    }

    private static readonly string[] RenderOptions =
        ["--output", "-o", "--camera", "--sampler", "--samples", "--seed", "--min-depth", "--max-depth", "--contrast",
         "--width", "--height", "--threads", "--stats", "--heatmap", "--help", "-h", "-?"];

    [Theory]
    [InlineData("--sampels", "--samples")]
    [InlineData("--ouput", "--output")]
    [InlineData("--treads", "--threads")]
    [InlineData("--heigth", "--height")]
    [InlineData("--maxdepth", "--max-depth")]
    [InlineData("--SEED", "--seed")]
    [InlineData("--heat", "--heatmap")]          // too far to edit, but a prefix of exactly one option
    public void AMistypedOptionSuggestsTheOneMeant(string typed, string meant) =>
        Assert.Equal([meant], Suggestions.Nearest(typed, RenderOptions));

    [Theory]
    [InlineData("jitterd", "jittered")]
    [InlineData("jittred", "jittered")]
    [InlineData("Jittered", "jittered")]
    [InlineData("hamersley", "hammersley")]
    [InlineData("sobel", "sobol")]
    [InlineData("adaptiv", "adaptive")]
    public void AMistypedSamplerSuggestsTheOneMeant(string typed, string meant) =>
        Assert.Equal([meant], Suggestions.Nearest(typed, ["regular", "random", "jittered", "cmj", "multijittered", "nrooks", "hammersley", "sobol", "adaptive"]));

    [Theory]
    [InlineData("persp", "perspective")]
    [InlineData("ortho", "orthographic")]
    [InlineData("perspectiv", "perspective")]
    public void APrefixOfACameraSuggestsIt(string typed, string meant) =>
        Assert.Equal([meant], Suggestions.Nearest(typed, ["perspective", "orthographic"]));

    [Fact]
    public void EqualCandidatesAreAllSuggestedInTheirOrder()
    {
        Assert.Equal(["--sampler", "--samples"], Suggestions.Nearest("--samp", RenderOptions));  // a prefix of both
        Assert.Equal(["--sampler", "--samples"], Suggestions.Nearest("--sample", RenderOptions)); // one letter from both
    }

    [Theory]
    [InlineData("--bogus")]
    [InlineData("fisheye")]
    [InlineData("x")]
    [InlineData("--")]
    [InlineData("--wi")]    // a prefix of --width, but two letters say too little
    public void NothingCloseSuggestsNothing(string typed)
    {
        Assert.Empty(Suggestions.Nearest(typed, [.. RenderOptions, "perspective", "orthographic"]));
        Assert.Equal("", Suggestions.DidYouMean(typed, [.. RenderOptions, "perspective", "orthographic"]));
    }

    [Fact]
    public void DidYouMeanIsAClauseForTheErrorLine()
    {
        Assert.Equal("; did you mean '--samples'?", Suggestions.DidYouMean("--sampels", RenderOptions));
        Assert.Equal("; did you mean '--sampler' or '--samples'?", Suggestions.DidYouMean("--samp", RenderOptions));
    }
}
