using System.Globalization;
using System.Text.Json;

namespace MyLab;

#if (en)
/// <summary>
/// The compiler's warnings that point at a likely mistake in the lab (a variable never used, code that never runs),
/// with file and line. Warnings do not stop the build: the lab builds and its checks run, and this list says what to
/// look at. The build writes them to build-warnings.sarif beside the program (Lab.csproj, ErrorLog).
/// </summary>
#else
/// <summary>
/// Ostrzeżenia kompilatora, które wskazują prawdopodobny błąd w laboratorium (zmienna, której nic nie używa, kod,
/// który nigdy się nie wykona), z plikiem i wierszem. Ostrzeżenia nie zatrzymują budowania: laboratorium się buduje,
/// testy działają, a ta lista mówi, na co spojrzeć. Budowanie zapisuje je do build-warnings.sarif obok programu
/// (Lab.csproj, ErrorLog).
/// </summary>
#endif
internal static class BuildWarnings
{
#if (en)
    /// <summary>Prints one line per warning; returns how many there are (0 where the build left no list).</summary>
#else
    /// <summary>Wypisuje po wierszu na ostrzeżenie; zwraca ich liczbę (0, gdy budowanie nie zostawiło listy).</summary>
#endif
    public static int Report(TextWriter output)
    {
        string path = Path.Combine(AppContext.BaseDirectory, "build-warnings.sarif");
        if (!File.Exists(path))
        {
            return 0;
        }

        var lines = new SortedSet<string>(StringComparer.Ordinal);
        try
        {
            using JsonDocument log = JsonDocument.Parse(File.ReadAllText(path));
            foreach (JsonElement run in log.RootElement.GetProperty("runs").EnumerateArray())
            {
                if (!run.TryGetProperty("results", out JsonElement results))
                {
                    continue;
                }

                foreach (JsonElement result in results.EnumerateArray())
                {
                    if (Line(result) is { } line)
                    {
                        lines.Add(line);
                    }
                }
            }
        }
        catch (Exception e) when (e is JsonException or KeyNotFoundException or InvalidOperationException or IOException)
        {
#if (en)
            // a list half written by a build still running: nothing to say
#else
            // lista w połowie zapisana przez trwające budowanie: nie ma czego wypisać
#endif
            return 0;
        }

        foreach (string line in lines)
        {
            output.WriteLine(line);
        }

        return lines.Count;
    }

#if (en)
    /// <summary>A warning the lab explains, as one line; null for any other.</summary>
#else
    /// <summary>Ostrzeżenie, które laboratorium objaśnia, jako jeden wiersz; null dla każdego innego.</summary>
#endif
    private static string? Line(JsonElement result)
    {
        string rule = result.TryGetProperty("ruleId", out JsonElement id) ? id.GetString() ?? "" : "";
        string message = result.TryGetProperty("message", out JsonElement m) && m.TryGetProperty("text", out JsonElement text) ? text.GetString() ?? "" : "";
        string? name = Quoted(message);
        string? explained = rule switch
        {
#if (en)
            "CS0219" => $"the variable {name} is given a value nothing reads",
            "CS0168" => $"the variable {name} is declared and never used",
            "CS0162" => "code that never runs (after a return, throw, break or continue)",
            "CS1717" => "a variable assigned to itself",
            "CS8321" => $"the local function {name} is never called",
            "CS0642" => "an empty statement after if, for or while (a stray ;)",
            "CS1718" => "a comparison of a variable with itself",
#else
            "CS0219" => $"zmienna {name} dostaje wartość, której nic nie czyta",
            "CS0168" => $"zmienna {name} jest zadeklarowana, ale nigdy nieużyta",
            "CS0162" => "kod, który nigdy się nie wykona (po return, throw, break lub continue)",
            "CS1717" => "przypisanie zmiennej do niej samej",
            "CS8321" => $"funkcja lokalna {name} nie jest nigdzie wywołana",
            "CS0642" => "pusta instrukcja po if, for lub while (zbędny średnik)",
            "CS1718" => "porównanie zmiennej z nią samą",
#endif
            _ => null,
        };
        if (explained is null || !result.TryGetProperty("locations", out JsonElement locations) || locations.GetArrayLength() == 0)
        {
            return null;
        }

        JsonElement physical = locations[0].GetProperty("physicalLocation");
        string file = physical.GetProperty("artifactLocation").GetProperty("uri").GetString() ?? "";
        int line = physical.TryGetProperty("region", out JsonElement region) && region.TryGetProperty("startLine", out JsonElement start) ? start.GetInt32() : 0;
        string where = Uri.TryCreate(file, UriKind.Absolute, out Uri? uri) && uri.IsFile ? uri.LocalPath : file;
        where = where.Replace('\\', '/');
        int lab = where.LastIndexOf("/src/Lab/", StringComparison.Ordinal);
        where = lab >= 0 ? where[(lab + 1)..] : Path.GetFileName(where);
#if (en)
        return string.Create(CultureInfo.InvariantCulture, $"  warning        {where}:{line}: {explained} ({rule})");
#else
        return string.Create(CultureInfo.InvariantCulture, $"  ostrzeżenie          {where}:{line}: {explained} ({rule})");
#endif
    }

#if (en)
    /// <summary>The first name in quotes in the compiler's message ('licznik'), with its quotes; null without one.</summary>
#else
    /// <summary>Pierwsza nazwa w apostrofach w komunikacie kompilatora ('licznik'), z apostrofami; null, gdy jej nie ma.</summary>
#endif
    private static string? Quoted(string message)
    {
        int open = message.IndexOf('\'', StringComparison.Ordinal);
        int close = open < 0 ? -1 : message.IndexOf('\'', open + 1);
        return close > open ? message[open..(close + 1)] : null;
    }
}
