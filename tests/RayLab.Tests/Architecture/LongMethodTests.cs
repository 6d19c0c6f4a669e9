using System.Runtime.CompilerServices;
using System.Text.RegularExpressions;

namespace RayLab.Tests.Architecture;

/// <summary>
/// A method over <see cref="Limit"/> lines in <c>src/</c> carries a one-line reason: a comment <c>// Long: …</c>
/// among the lines just above its signature (with its attributes). Lines are counted from the signature to the
/// closing brace. The methods are found by <see cref="SourceMethods"/>, a brace counter over the source text.
/// </summary>
public sealed partial class LongMethodTests
{
    private const int Limit = 60;

    // Long methods without a reason yet (file name: method); this list may only shrink, and is empty.
    private static readonly string[] Pending = [];

    [Fact]
    public void Every_method_over_60_lines_in_src_says_why_it_is_long()
    {
        string src = Path.Combine(RepositoryRoot(), "src");
        var offenders = new List<string>();
        var unexplained = new HashSet<string>();
        int methods = 0;
        foreach (string file in SourceFiles(src))
        {
            string text = File.ReadAllText(file);
            string[] lines = text.Split('\n');
            string relative = Path.GetRelativePath(src, file).Replace('\\', '/');
            foreach (SourceMethods.Method method in SourceMethods.Find(text))
            {
                methods++;
                if (method.Lines <= Limit || SourceMethods.HasReason(lines, method.SignatureLine))
                {
                    continue;
                }

                string name = $"{Path.GetFileName(file)}: {method.Name}";
                unexplained.Add(name);
                if (!Pending.Contains(name))
                {
                    offenders.Add($"{relative}:{method.SignatureLine} {method.Name} is {method.Lines} lines");
                }
            }
        }

        Assert.True(methods > 300, $"the parser found only {methods} methods in {src}");
        string[] stale = [.. Pending.Except(unexplained)];
        Assert.True(stale.Length == 0, $"No longer long or now explained, so take them off the pending list: {string.Join(", ", stale)}");
        Assert.True(offenders.Count == 0, $"Shorten these methods or give each a '// Long: reason' line above it:\n{string.Join('\n', offenders)}");
    }

    [Fact]
    public void The_parser_measures_methods_and_sees_past_strings_comments_and_local_functions()
    {
        const string Source = """
            namespace N;

            internal sealed class C(int x)
            {
                private readonly Func<int, int> _f = v => { return v; };
                private readonly List<int> _l = new List<int>(1) { 2 };

                public C() : this(1)
                {
                }

                // Long: a reason.
                [Obsolete("}")]
                private static (int A, int B) Pair(string s) where T : struct
                {
                    string t = "{ \" {";
                    string u = $"{s} {{ {(s.Length > 0 ? "}" : "{")}";
                    char c = '{';
                    /* { */
                    int Local() { return 1; }
                    if (s.Length > 0) { return (1, 2); }
                    return (Local(), 3);
                }

                public int Value => x;

                public static C operator +(C a, C b) { return a; }

                private static List<T> Make<T, U>(T t) where T : struct { return [t]; }

                extension(string s)
                {
                    public int Twice(int k = 2) { return k * s.Length; }
                }
            }
            """;
        string[] lines = Source.Split('\n');
        SourceMethods.Method[] found = [.. SourceMethods.Find(Source)];
        Assert.Equal(["C", "Pair", "operator", "Make", "Twice"], found.Select(m => m.Name));
        SourceMethods.Method pair = found[1];
        Assert.Equal((14, 10), (pair.SignatureLine, pair.Lines));
        Assert.True(SourceMethods.HasReason(lines, pair.SignatureLine));
        Assert.False(SourceMethods.HasReason(lines, found[0].SignatureLine));
    }

    private static IEnumerable<string> SourceFiles(string src) =>
        Directory.EnumerateFiles(src, "*.cs", SearchOption.AllDirectories)
            .Where(f => !f.Contains($"{Path.DirectorySeparatorChar}obj{Path.DirectorySeparatorChar}", StringComparison.Ordinal)
                && !f.Contains($"{Path.DirectorySeparatorChar}bin{Path.DirectorySeparatorChar}", StringComparison.Ordinal))
            .Order(StringComparer.Ordinal);

    private static string RepositoryRoot([CallerFilePath] string path = "") =>
        Path.GetFullPath(Path.Combine(Path.GetDirectoryName(path)!, "..", "..", ".."));
}

/// <summary>
/// Finds the methods of a C# source text without a compiler: comments and literals are blanked, then each
/// <c>{</c> is classed by the text before it (back to the last <c>;</c>, <c>{</c> or <c>}</c>) as a type, a
/// method (constructors and operators included; the type keywords count before the first parenthesis only, so
/// not in a <c>where</c> clause), or any other block, and a
/// method runs to its matching <c>}</c>. Expression-bodied members and blocks inside methods (local functions,
/// lambdas) count as part of what holds them.
/// </summary>
internal static partial class SourceMethods
{
    private static readonly HashSet<string> Keywords =
        ["if", "else", "for", "foreach", "while", "do", "switch", "try", "catch", "finally", "using", "lock", "fixed",
         "checked", "unchecked", "unsafe", "return", "new", "when", "in", "is", "nameof", "typeof", "sizeof", "default"];

    /// <summary>A method: its name, the 1-based line of its signature, and its length in lines (signature to closing brace).</summary>
    public readonly record struct Method(string Name, int SignatureLine, int Lines);

    /// <summary>True when a line <c>// Long: reason</c> stands among the comment and attribute lines just above <paramref name="signatureLine"/>.</summary>
    public static bool HasReason(string[] lines, int signatureLine)
    {
        for (int k = signatureLine - 2; k >= 0; k--)
        {
            string line = lines[k].Trim();
            if (line.StartsWith("// Long:", StringComparison.Ordinal) && line.Length > "// Long: ".Length)
            {
                return true;
            }

            if (!line.StartsWith('[') && !line.StartsWith("//", StringComparison.Ordinal))
            {
                return false;
            }
        }

        return false;
    }

    /// <summary>The methods with a block body in <paramref name="source"/>, in the order they close.</summary>
    public static IEnumerable<Method> Find(string source)
    {
        string code = Blank(source);
        string[] lines = source.Split('\n');
        var stack = new Stack<(bool Type, bool Method, int Open, int First, string Name)>();
        int headerStart = 0, parens = 0;
        for (int pos = 0; pos < code.Length; pos++)
        {
            char c = code[pos];
            if (c == '(')
            {
                parens++;
            }
            else if (c == ')')
            {
                parens--;
            }
            else if (c == ';' && parens == 0)
            {
                headerStart = pos + 1;
            }
            else if (c == '{')
            {
                string raw = code[headerStart..pos];
                string header = Attributes().Replace(raw, "").Trim();
                bool inMethod = stack.Any(s => s.Method);
                bool inType = !inMethod && (stack.Count == 0 || stack.Peek().Type);
                bool type = !inMethod && (TypeHeader().IsMatch(header.Split('(')[0]) || Extension().IsMatch(header));
                string? name = inType && !type ? MethodName(header) : null;
                int first = headerStart + (raw.Length - raw.TrimStart().Length);
                stack.Push((type, name is not null, pos, first, name ?? ""));
                headerStart = pos + 1;
            }
            else if (c == '}')
            {
                (_, bool method, _, int first, string name) = stack.Pop();
                if (method)
                {
                    int signature = LineOf(code, first);
                    while (lines[signature - 1].TrimStart().StartsWith('['))
                    {
                        signature++;
                    }

                    yield return new Method(name, signature, LineOf(code, pos) - signature + 1);
                }

                headerStart = pos + 1;
            }
        }
    }

    // The name of the member whose header this is, when it has a parameter list: the identifier just before the first
    // "(" or "<…>(" (so not a tuple return type's), or "operator"; null for any other block.
    private static string? MethodName(string header)
    {
        if (!ParameterListEnd().IsMatch(header))
        {
            return null;
        }

        if (Operator().IsMatch(header))
        {
            return "operator";
        }

        string? name = NameBeforeParameters(header);
        return name is not null && !Keywords.Contains(name) && !header.Split('(')[0].Contains('=', StringComparison.Ordinal) ? name : null;
    }

    // The identifier right before the first "(" that follows one (after its type arguments, if any).
    private static string? NameBeforeParameters(string header)
    {
        for (int i = 0; i < header.Length; i++)
        {
            if (header[i] != '(')
            {
                continue;
            }

            int j = i - 1;
            if (j >= 0 && header[j] == '>')
            {
                for (int depth = 0; j >= 0; j--)
                {
                    depth += header[j] == '>' ? 1 : header[j] == '<' ? -1 : 0;
                    if (depth == 0)
                    {
                        j--;
                        break;
                    }
                }
            }

            int end = j + 1;
            while (j >= 0 && (char.IsLetterOrDigit(header[j]) || header[j] == '_'))
            {
                j--;
            }

            if (end > j + 1)
            {
                return header[(j + 1)..end];
            }
        }

        return null;
    }

    private static int LineOf(string code, int pos)
    {
        int line = 1;
        for (int i = 0; i < pos; i++)
        {
            line += code[i] == '\n' ? 1 : 0;
        }

        return line;
    }

    // The source with every comment, string and character literal replaced by spaces, newlines kept.
    private static string Blank(string s)
    {
        char[] o = s.ToCharArray();
        int i = 0, n = s.Length;
        while (i < n)
        {
            int end = s[i] switch
            {
                '/' when i + 1 < n && s[i + 1] == '/' => s.IndexOf('\n', i) is int e and >= 0 ? e : n,
                '/' when i + 1 < n && s[i + 1] == '*' => s.IndexOf("*/", i + 2, StringComparison.Ordinal) is int e and >= 0 ? e + 2 : n,
                '"' or '$' or '@' when StringStart(s, i) is int q and >= 0 => StringEnd(s, i, q),
                '\'' => CharEnd(s, i),
                _ => -1,
            };
            if (end < 0)
            {
                i++;
                continue;
            }

            for (int k = i; k < end; k++)
            {
                o[k] = o[k] == '\n' ? '\n' : ' ';
            }

            i = end;
        }

        return new string(o);
    }

    // Where the quotes of a string literal starting at i (after its $ and @ prefixes) begin, or −1.
    private static int StringStart(string s, int i)
    {
        int j = i;
        while (j < s.Length && s[j] is '$' or '@')
        {
            j++;
        }

        return j < s.Length && s[j] == '"' ? j : -1;
    }

    private static int StringEnd(string s, int i, int q)
    {
        string prefix = s[i..q];
        int n = s.Length;
        if (s.AsSpan(q).StartsWith("\"\"\""))
        {
            int r = q;
            while (r < n && s[r] == '"')
            {
                r++;
            }

            int close = s.IndexOf(s[q..r], r, StringComparison.Ordinal);
            return close < 0 ? n : close + (r - q);
        }

        bool verbatim = prefix.Contains('@', StringComparison.Ordinal), interpolated = prefix.Contains('$', StringComparison.Ordinal);
        int depth = 0;
        for (int e = q + 1; e < n; e++)
        {
            char c = s[e];
            if (depth > 0)
            {
                if (c == '"' || c == '\'')
                {
                    e = c == '"' && StringStart(s, e) is int inner and >= 0 ? StringEnd(s, e, inner) - 1 : CharEnd(s, e) - 1;
                }
                else if (c == '{')
                {
                    depth++;
                }
                else if (c == '}')
                {
                    depth--;
                }
            }
            else if (c == '\\' && !verbatim)
            {
                e++;
            }
            else if (c == '"' && verbatim && e + 1 < n && s[e + 1] == '"')
            {
                e++;
            }
            else if (c == '"')
            {
                return e + 1;
            }
            else if (c == '{' && interpolated)
            {
                if (e + 1 < n && s[e + 1] == '{')
                {
                    e++;
                }
                else
                {
                    depth = 1;
                }
            }
        }

        return n;
    }

    private static int CharEnd(string s, int i)
    {
        int e = i + 1;
        while (e < s.Length && s[e] != '\'' && s[e] != '\n')
        {
            e += s[e] == '\\' ? 2 : 1;
        }

        return Math.Min(e + 1, s.Length);
    }

    [GeneratedRegex(@"^\s*(\[[^\]]*\]\s*)*")]
    private static partial Regex Attributes();

    [GeneratedRegex(@"\b(class|struct|interface|record|enum|namespace)\b")]
    private static partial Regex TypeHeader();

    [GeneratedRegex(@"^extension\s*(<[^()]*>)?\(")]
    private static partial Regex Extension();

    [GeneratedRegex(@"\)\s*((where\s[^{]*)|(:\s*(base|this)\s*\(.*\)))?$", RegexOptions.Singleline)]
    private static partial Regex ParameterListEnd();

    [GeneratedRegex(@"\boperator\s*[^\s(]+\s*\(")]
    private static partial Regex Operator();

}
