using System.CommandLine;
using System.CommandLine.Parsing;
using System.Globalization;

namespace RayLab.Cli;

/// <summary>
/// The one line a malformed command line gets: an unknown option or command with the nearest valid name
/// (<c>--sampels</c> → <c>--samples</c>), a number that does not parse named by its option, else the parser's message.
/// </summary>
internal static class CommandLineError
{
    public static string Describe(ParseResult parsed)
    {
        Command command = parsed.CommandResult.Command;
        string help = command is RootCommand ? "raylab --help" : $"raylab {command.Name} --help";
        return $"raylab: error: {Problem(parsed, command)} (see '{help}')";
    }

    private static string Problem(ParseResult parsed, Command command)
    {
        // A typo in an option also makes "--output is required" or an unexpected value: the typo is the news.
        if (parsed.UnmatchedTokens.Count > 0)
        {
            string token = parsed.UnmatchedTokens[0];
            IEnumerable<string> options = command.Options.Where(o => !o.Hidden).SelectMany(o => o.Aliases.Prepend(o.Name));
            IEnumerable<string> commands = command.Subcommands.Where(c => !c.Hidden).Select(c => c.Name);
            return token.StartsWith('-')
                ? $"unknown option '{token}'{Suggestions.DidYouMean(token, options)}"
                : command.Subcommands.Count > 0
                    ? $"unknown command '{token}'{Suggestions.DidYouMean(token, commands)}"
                    : $"unexpected argument '{token}'{Suggestions.DidYouMean(token, options)}";
        }

        ParseError first = parsed.Errors[0];
        if (first.SymbolResult is OptionResult { Tokens: [var value] } result && Expected(result.Option.ValueType, value.Value) is { } expected)
        {
            return $"{result.Option.Name}: expected {expected}, got '{value.Value}'";
        }

        return first.Message.TrimEnd('.');
    }

    // What a numeric option takes, when the token is not one (null when it parses or the option is not numeric).
    private static string? Expected(Type type, string token) => (Nullable.GetUnderlyingType(type) ?? type) switch
    {
        var t when t == typeof(int) && !int.TryParse(token, NumberStyles.Integer, CultureInfo.InvariantCulture, out _) =>
            "a whole number",
        var t when t == typeof(uint) && !uint.TryParse(token, NumberStyles.Integer, CultureInfo.InvariantCulture, out _) =>
            $"a whole number from 0 to {uint.MaxValue}",
        var t when t == typeof(double) && !double.TryParse(token, NumberStyles.Float, CultureInfo.InvariantCulture, out _) =>
            "a number",
        _ => null,
    };
}
