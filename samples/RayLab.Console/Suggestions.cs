namespace RayLab.Cli;

/// <summary>
/// "Did you mean …?" for a mistyped command, option or choice: the valid names nearest to what was typed, by
/// edit distance with adjacent transpositions (<c>--sampels</c> → <c>--samples</c>), or by prefix
/// (<c>persp</c> → <c>perspective</c>).
/// </summary>
public static class Suggestions
{
    /// <summary>
    /// The optimal-string-alignment distance (Damerau–Levenshtein without repeated edits of one substring):
    /// insertions, deletions, substitutions and swaps of two adjacent characters each cost 1. Ordinal, case-sensitive.
    /// </summary>
    /// <param name="a">One string.</param>
    /// <param name="b">The other.</param>
    /// <returns>The number of edits that turn <paramref name="a"/> into <paramref name="b"/>.</returns>
    public static int Distance(string a, string b)
    {
        ArgumentNullException.ThrowIfNull(a);
        ArgumentNullException.ThrowIfNull(b);

        // Three rows of the (|a|+1)×(|b|+1) table: the swap looks two rows back.
        var before = new int[b.Length + 1];
        var previous = new int[b.Length + 1];
        var current = new int[b.Length + 1];
        for (int j = 0; j <= b.Length; j++)
        {
            current[j] = j;
        }

        for (int i = 1; i <= a.Length; i++)
        {
            (before, previous, current) = (previous, current, before);
            current[0] = i;
            for (int j = 1; j <= b.Length; j++)
            {
                int cost = a[i - 1] == b[j - 1] ? 0 : 1;
                int best = Math.Min(Math.Min(previous[j] + 1, current[j - 1] + 1), previous[j - 1] + cost);
                if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                {
                    best = Math.Min(best, before[j - 2] + 1);
                }

                current[j] = best;
            }
        }

        return current[b.Length];
    }

    /// <summary>
    /// The candidates nearest to <paramref name="typed"/>, ignoring case: those at the smallest distance when it
    /// is small for the word's length (1 for up to 5 letters, 2 up to 8, 3 beyond; leading dashes do not count),
    /// else those that start with what was typed (3 letters or more). Empty when nothing is close.
    /// </summary>
    /// <param name="typed">What the user typed.</param>
    /// <param name="candidates">The valid names, in the order to list ties.</param>
    /// <returns>The suggestions, in candidate order; usually one.</returns>
    public static IReadOnlyList<string> Nearest(string typed, IEnumerable<string> candidates)
    {
        ArgumentNullException.ThrowIfNull(typed);
        ArgumentNullException.ThrowIfNull(candidates);
        string word = typed.ToLowerInvariant();
        int letters = word.TrimStart('-').Length;
        if (letters == 0)
        {
            return [];
        }

        string[] names = [.. candidates.Distinct(StringComparer.Ordinal)];
        int[] distances = [.. names.Select(n => Distance(word, n.ToLowerInvariant()))];
        int nearest = distances.Length == 0 ? int.MaxValue : distances.Min();
        if (nearest <= (letters <= 5 ? 1 : letters <= 8 ? 2 : 3))
        {
            return [.. names.Where((_, i) => distances[i] == nearest)];
        }

        return letters >= 3
            ? [.. names.Where(n => n.StartsWith(typed, StringComparison.OrdinalIgnoreCase))]
            : [];
    }

    /// <summary>
    /// The suggestion as a clause for an error line: <c>; did you mean '--samples'?</c>, or
    /// <c>; did you mean '--sampler' or '--samples'?</c>; empty when nothing is close.
    /// </summary>
    /// <param name="typed">What the user typed.</param>
    /// <param name="candidates">The valid names.</param>
    /// <returns>The clause, or an empty string.</returns>
    public static string DidYouMean(string typed, IEnumerable<string> candidates)
    {
        IReadOnlyList<string> near = Nearest(typed, candidates);
        return near.Count == 0 ? "" : $"; did you mean {string.Join(" or ", near.Select(n => $"'{n}'"))}?";
    }
}
