using System.Text.Json;

namespace RayLab.Grading;

/// <summary>
/// The checks' list of what a lab may use from other assemblies (the lab's <c>tests/Lab.Tests/uses.json</c>, which the
/// class kit's pinned checks carry too): the assemblies besides .NET's own, the members allowed and forbidden, and which
/// lab class belongs to which section of the lab.
/// </summary>
/// <remarks>
/// <para>A rule names a namespace with everything in it (<c>System.*</c>), a type with its members and nested types
/// (<c>RayLab.Double3</c>), or one member (<c>System.Type::GetTypeFromHandle</c>, <c>RayLab.Scene::.ctor</c>).
/// For each use the most specific rule decides (a member over a type over a namespace; a longer name over a shorter);
/// where an allowed and a forbidden rule are equally specific, the forbidden one does.</para>
/// <para>A use no rule allows is refused: from a RayLab assembly as part of the lab to write, from any other as not on
/// the list. Native methods and calls through function pointers are always refused.</para>
/// </remarks>
public sealed class UseList
{
    private readonly (string Pattern, int Rank)[] _allowed;
    private readonly (string Pattern, int Rank, string Reason)[] _forbidden;
    private readonly HashSet<string> _assemblies;

    private UseList(Dictionary<string, string> sections, string[] programOnly, string[] assemblies, string[] allowed, Dictionary<string, string> forbidden)
    {
        Sections = sections;
        ProgramOnly = new HashSet<string>(programOnly, StringComparer.Ordinal);
        _assemblies = new HashSet<string>(assemblies, StringComparer.Ordinal);
        _allowed = [.. allowed.Select(p => (p, Rank(p)))];
        _forbidden = [.. forbidden.Select(f => (f.Key, Rank(f.Key), f.Value))];
    }

    /// <summary>Each lab class's section (<c>LabOrthoCamera</c> → <c>3.1</c>).</summary>
    public IReadOnlyDictionary<string, string> Sections { get; }

    /// <summary>
    /// The classes of the lab that only its program runs, not its checks (the method lab's <c>Program</c>, which
    /// renders the exact image to compare with): their uses count only where a section's class reaches them.
    /// </summary>
    public IReadOnlySet<string> ProgramOnly { get; }

    /// <summary>Reads a list file.</summary>
    /// <param name="path">The file (uses.json).</param>
    /// <returns>The list.</returns>
    /// <exception cref="FormatException">The file is not a valid list: the message names the file and the field.</exception>
    public static UseList Load(string path)
    {
        ArgumentException.ThrowIfNullOrEmpty(path);
        return Parse(File.ReadAllText(path), path);
    }

    /// <summary>Reads a list from its JSON text.</summary>
    /// <param name="json">The text: <c>{"sections": {class: section}, "programOnly": [class, ...], "assemblies": [...], "allowed": [rule, ...], "forbidden": {rule: reason}}</c>.</param>
    /// <param name="source">Where the text comes from, for the messages.</param>
    /// <returns>The list.</returns>
    /// <exception cref="FormatException">The text is not a valid list: the message names the source and the field.</exception>
    public static UseList Parse(string json, string source)
    {
        ArgumentNullException.ThrowIfNull(json);
        ArgumentNullException.ThrowIfNull(source);
        try
        {
            using JsonDocument document = JsonDocument.Parse(json, new JsonDocumentOptions { CommentHandling = JsonCommentHandling.Skip, AllowTrailingCommas = true });
            JsonElement root = document.RootElement;
            if (root.ValueKind != JsonValueKind.Object)
            {
                throw new FormatException($"{source}: expected a JSON object");
            }

            var sections = new Dictionary<string, string>(StringComparer.Ordinal);
            if (root.TryGetProperty("sections", out JsonElement s))
            {
                foreach (JsonProperty p in Object(s, source, "sections").EnumerateObject())
                {
                    sections[p.Name] = Text(p.Value, source, $"sections.{p.Name}");
                }
            }

            string[] programOnly = root.TryGetProperty("programOnly", out JsonElement po) ? Texts(po, source, "programOnly") : [];
            string[] assemblies = root.TryGetProperty("assemblies", out JsonElement a) ? Texts(a, source, "assemblies") : [];
            string[] allowed = root.TryGetProperty("allowed", out JsonElement al) ? Texts(al, source, "allowed") : [];
            var forbidden = new Dictionary<string, string>(StringComparer.Ordinal);
            if (root.TryGetProperty("forbidden", out JsonElement f))
            {
                foreach (JsonProperty p in Object(f, source, "forbidden").EnumerateObject())
                {
                    forbidden[Rule(p.Name, source, "forbidden")] = Text(p.Value, source, $"forbidden.{p.Name}");
                }
            }

            foreach (string rule in allowed)
            {
                Rule(rule, source, "allowed");
            }

            return new UseList(sections, programOnly, assemblies, allowed, forbidden);
        }
        catch (JsonException e)
        {
            throw new FormatException($"{source}: not valid JSON ({e.Message})", e);
        }
    }

    /// <summary>Whether the list lets a lab make <paramref name="use"/>, and if not, why.</summary>
    /// <param name="use">The use.</param>
    /// <returns>The verdict.</returns>
    public UseVerdict Judge(ForeignUse use)
    {
        ArgumentNullException.ThrowIfNull(use);
        switch (use.Kind)
        {
            case UseKind.NativeMethod:
                return new UseVerdict(UseRefusal.Forbidden, "native code");
            case UseKind.FunctionPointer:
                return new UseVerdict(UseRefusal.Forbidden, "a function pointer");
        }

        if (!use.FromBaseLibrary && !_assemblies.Contains(use.Assembly))
        {
            return new UseVerdict(UseRefusal.NotListed, null);
        }

        string name = use.Member.Length == 0 ? use.Type : $"{use.Type}::{use.Member}";
        int allowed = _allowed.Where(r => Matches(r.Pattern, name)).Select(r => r.Rank).DefaultIfEmpty(-1).Max();
        (string Pattern, int Rank, string Reason) forbidden = _forbidden.Where(r => Matches(r.Pattern, name)).OrderByDescending(r => r.Rank).FirstOrDefault();
        if (forbidden.Pattern is not null && forbidden.Rank >= allowed)
        {
            return new UseVerdict(UseRefusal.Forbidden, forbidden.Reason);
        }

        if (allowed >= 0)
        {
            return new UseVerdict(UseRefusal.None, null);
        }

        return use.Assembly.StartsWith("RayLab", StringComparison.Ordinal)
            ? new UseVerdict(UseRefusal.ToWrite, null)
            : new UseVerdict(UseRefusal.NotListed, null);
    }

    /// <summary>
    /// Every use of <paramref name="uses"/> the list refuses, each with the sections it fails: its class's section; for a
    /// helper class, the sections of the classes whose methods reach it; for code no section reaches (a static
    /// constructor or a module initializer can still run it), every section, but for a class only the program runs
    /// (<see cref="ProgramOnly"/>), none.
    /// </summary>
    /// <param name="uses">The lab assembly's uses.</param>
    /// <returns>The refused uses, in the lab's metadata order.</returns>
    public IReadOnlyList<UseFinding> Check(AssemblyUses uses)
    {
        ArgumentNullException.ThrowIfNull(uses);
        string[] all = [.. Sections.Values.Distinct(StringComparer.Ordinal)];
        var findings = new List<UseFinding>();
        foreach (ForeignUse use in uses.Uses)
        {
            UseVerdict verdict = Judge(use);
            if (verdict.Refusal == UseRefusal.None)
            {
                continue;
            }

            string[] sections;
            if (Sections.TryGetValue(use.LabType, out string? own))
            {
                sections = [own];
            }
            else
            {
                sections = [.. uses.ReachedFrom(use.LabType, Sections.ContainsKey).Where(Sections.ContainsKey).Select(t => Sections[t]).Distinct(StringComparer.Ordinal).Order(StringComparer.Ordinal)];
                if (sections.Length == 0 && ProgramOnly.Contains(use.LabType))
                {
                    continue;
                }

                if (sections.Length == 0)
                {
                    sections = all;
                }
            }

            findings.Add(new UseFinding(sections, use, verdict));
        }

        return findings;
    }

    private static bool Matches(string pattern, string name)
    {
        if (pattern.EndsWith(".*", StringComparison.Ordinal))
        {
            string space = pattern[..^2];
            return name.StartsWith(space, StringComparison.Ordinal) && name.Length > space.Length && name[space.Length] == '.';
        }

        if (pattern.Contains("::", StringComparison.Ordinal))
        {
            return name == pattern;
        }

        return name == pattern
            || (name.StartsWith(pattern, StringComparison.Ordinal) && name.Length > pattern.Length && name[pattern.Length] is ':' or '+' or '`');
    }

    private static int Rank(string pattern) =>
        pattern.EndsWith(".*", StringComparison.Ordinal) ? pattern.Length
        : pattern.Contains("::", StringComparison.Ordinal) ? 20_000 + pattern.Length
        : 10_000 + pattern.Length;

    private static string Rule(string rule, string source, string field)
    {
        int star = rule.IndexOf('*', StringComparison.Ordinal);
        if (rule.Length == 0 || rule.Any(char.IsWhiteSpace) || (star >= 0 && (star != rule.Length - 1 || !rule.EndsWith(".*", StringComparison.Ordinal))))
        {
            throw new FormatException($"{source}: {field}: '{rule}' is not a rule: expected Namespace.*, Namespace.Type or Namespace.Type::Member");
        }

        return rule;
    }

    private static JsonElement Object(JsonElement e, string source, string field) =>
        e.ValueKind == JsonValueKind.Object ? e : throw new FormatException($"{source}: {field}: expected an object");

    private static string Text(JsonElement e, string source, string field) =>
        e.ValueKind == JsonValueKind.String && e.GetString() is { Length: > 0 } text ? text : throw new FormatException($"{source}: {field}: expected a non-empty string");

    private static string[] Texts(JsonElement e, string source, string field) =>
        e.ValueKind == JsonValueKind.Array
            ? [.. e.EnumerateArray().Select((x, i) => Text(x, source, $"{field}[{i}]"))]
            : throw new FormatException($"{source}: {field}: expected an array of strings");
}

/// <summary>Why a use is refused.</summary>
public enum UseRefusal
{
    /// <summary>It is allowed.</summary>
    None,

    /// <summary>It is RayLab's own version of something the lab asks the student to write.</summary>
    ToWrite,

    /// <summary>A forbidden rule names it (reflection, processes, native code, …).</summary>
    Forbidden,

    /// <summary>It comes from an assembly the list does not name, or no rule allows it.</summary>
    NotListed,
}

/// <summary>The list's verdict on one use.</summary>
/// <param name="Refusal">Why it is refused, or <see cref="UseRefusal.None"/>.</param>
/// <param name="Reason">For <see cref="UseRefusal.Forbidden"/>, the forbidden rule's reason (e.g. <c>reflection</c>).</param>
public readonly record struct UseVerdict(UseRefusal Refusal, string? Reason);

/// <summary>A use the list refuses, with the lab sections it fails.</summary>
/// <param name="Sections">The sections it fails.</param>
/// <param name="Use">The use.</param>
/// <param name="Verdict">Why it is refused.</param>
public sealed record UseFinding(IReadOnlyList<string> Sections, ForeignUse Use, UseVerdict Verdict)
{
    /// <summary>
    /// One line, in English or Polish: <c>LabOrthoCamera.GetRay uses RayLab's OrthoCamera.GetImagePlane: the lab asks
    /// you to write it</c>, without the section (see <see cref="Sections"/>).
    /// </summary>
    /// <param name="polish">Polish instead of English.</param>
    /// <returns>The line.</returns>
    public string Message(bool polish)
    {
        string where = Use.LabMethod.StartsWith('(') ? Use.LabType : $"{Use.LabType}.{Use.LabMethod}";
        string owner = Use.Assembly.StartsWith("RayLab", StringComparison.Ordinal) ? "RayLab" : Use.Assembly;
        return (Verdict.Refusal, polish) switch
        {
            (UseRefusal.ToWrite, false) => $"{where} uses RayLab's {Use.Display}: the lab asks you to write it",
            (UseRefusal.ToWrite, true) => $"{where} używa {Use.Display} z RayLab: to część laboratorium do napisania samodzielnie",
            (UseRefusal.Forbidden, false) => $"{where} uses {Verdict.Reason} ({Use.Display}), which the lab does not allow",
            (UseRefusal.Forbidden, true) => $"{where} używa {Polish(Verdict.Reason)} ({Use.Display}), na co laboratorium nie pozwala",
            (_, false) => $"{where} uses {owner}'s {Use.Display}, which is not on the lab's list of what it may use",
            (_, true) => $"{where} używa {Use.Display} z {owner}, czego nie ma na liście tego, czego laboratorium pozwala używać",
        };
    }

    /// <summary>The message with the sections in front: <c>3.1: LabOrthoCamera.GetRay uses …</c>.</summary>
    /// <param name="polish">Polish instead of English.</param>
    /// <returns>The line.</returns>
    public string Line(bool polish) => $"{string.Join(", ", Sections)}: {Message(polish)}";

    private static string? Polish(string? reason) => reason switch
    {
        "reflection" => "refleksji",
        "dynamic code" => "kodu generowanego w czasie działania",
        "assembly loading" => "ładowania zestawów",
        "native code" => "kodu natywnego",
        "a function pointer" => "wskaźnika do funkcji",
        "processes" => "uruchamiania procesów",
        "unsafe memory access" => "niebezpiecznego dostępu do pamięci",
        "the network" => "sieci",
        "the exact renderer" => "dokładnego renderera",
        "the grader's own code" => "kodu oceniającego",
        "code that runs when the lab loads" => "kodu uruchamianego przy ładowaniu laboratorium",
        _ => reason,
    };
}
