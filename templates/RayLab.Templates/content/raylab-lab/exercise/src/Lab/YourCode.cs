using System.Diagnostics;
using System.Globalization;
using System.Reflection;

namespace MyLab;

#if (en)
/// <summary>
/// Where in your code an exception was thrown, for the program's messages: the first frame of its stack in this
/// project, as "src/Lab/File.cs:line, Class.Method".
/// </summary>
#else
/// <summary>
/// Gdzie w Twoim kodzie został rzucony wyjątek, do komunikatów programu: pierwsza ramka jego stosu w tym projekcie,
/// jako „src/Lab/Plik.cs:wiersz, Klasa.Metoda”.
/// </summary>
#endif
internal static class YourCode
{
#if (en)
    /// <summary>The exception your code threw, out of the wrappers a loop puts around it (Parallel.For's AggregateException).</summary>
#else
    /// <summary>Wyjątek rzucony przez Twój kod, wyjęty z opakowań, w które wkłada go pętla (AggregateException z Parallel.For).</summary>
#endif
    public static Exception Unwrapped(Exception e)
    {
        while (true)
        {
            switch (e)
            {
                case AggregateException { InnerExceptions.Count: > 0 } a:
                    e = a.InnerExceptions[0];
                    break;
                case TargetInvocationException { InnerException: { } inner }:
                    e = inner;
                    break;
                default:
                    return e;
            }
        }
    }

#if (en)
    /// <summary>"Type: message (src/Lab/File.cs:line, Class.Method)" for an exception your code threw.</summary>
#else
    /// <summary>„Typ: komunikat (src/Lab/Plik.cs:wiersz, Klasa.Metoda)” dla wyjątku rzuconego przez Twój kod.</summary>
#endif
    public static string Describe(Exception e)
    {
        Exception thrown = Unwrapped(e);
        return $"{thrown.GetType().Name}: {thrown.Message} ({Where(thrown)})";
    }

#if (en)
    /// <summary>The first frame of the exception's stack in this project, as "src/Lab/File.cs:line, Class.Method".</summary>
#else
    /// <summary>Pierwsza ramka stosu wyjątku w tym projekcie, jako „src/Lab/Plik.cs:wiersz, Klasa.Metoda”.</summary>
#endif
    public static string Where(Exception e)
    {
        Assembly yours = typeof(YourCode).Assembly;
        foreach (StackFrame frame in new StackTrace(e, fNeedFileInfo: true).GetFrames())
        {
            MethodBase? method = frame.GetMethod();
            if (method?.DeclaringType is not { } type || type.Assembly != yours)
            {
                continue;
            }

            while (type.Name.StartsWith('<') && type.DeclaringType is { } outer)
            {
#if (en)
                // a lambda's or a local function's class: the class it is written in
#else
                // klasa lambdy albo funkcji lokalnej: klasa, w której ją napisano
#endif
                type = outer;
            }

            if (type == typeof(Progress))
            {
#if (en)
                // a probe's own function, which your code called: the place is your code's frame below it
#else
                // funkcja samej sondy, którą wywołał Twój kod: miejscem jest ramka Twojego kodu pod nią
#endif
                continue;
            }

            string name = method.Name.StartsWith('<') ? method.Name[1..method.Name.IndexOf('>', StringComparison.Ordinal)]
                : method.IsConstructor ? type.Name : method.Name;
            string? file = frame.GetFileName();
            if (file is null || frame.GetFileLineNumber() == 0)
            {
                return $"{type.Name}.{name}";
            }

            string path = file.Replace('\\', '/');
            int lab = path.LastIndexOf("/src/Lab/", StringComparison.Ordinal);
            path = lab >= 0 ? path[(lab + 1)..] : Path.GetFileName(path);
            return string.Create(CultureInfo.InvariantCulture, $"{path}:{frame.GetFileLineNumber()}, {type.Name}.{name}");
        }

#if (en)
        return "outside your code";
#else
        return "poza Twoim kodem";
#endif
    }
}
