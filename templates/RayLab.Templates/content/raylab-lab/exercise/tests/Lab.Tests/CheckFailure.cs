#if (en)
// In xUnit's namespace, as its own assertions' exceptions are: dotnet test then shows a failure's message as it is,
// not after the exception's type name.
#else
// W przestrzeni nazw xUnit, jak wyjątki jego własnych asercji: dotnet test pokazuje wtedy komunikat błędu taki, jaki
// jest, a nie po nazwie typu wyjątku.
#endif
namespace Xunit.Sdk;

#if (en)
/// <summary>
/// A check's failure as dotnet test shows it: the message, and a stack of the frames in the lab's own files only
/// (where <c>cause</c> was thrown, in your code or the check's, then the check that ran it), without the frames of
/// .NET's threads and reflection, which say nothing about your code.
/// </summary>
#else
/// <summary>
/// Błąd sprawdzenia tak, jak pokazuje go dotnet test: komunikat i stos z samymi ramkami z plików laboratorium (gdzie
/// rzucono <c>cause</c>, w Twoim kodzie albo w sprawdzeniu, potem sprawdzenie, które go wykonało), bez ramek wątków i
/// refleksji .NET, które nic nie mówią o Twoim kodzie.
/// </summary>
#endif
internal sealed class CheckFailure(string message, Exception? cause) : XunitException(message)
{
    public override string? StackTrace => string.Join(Environment.NewLine,
        new[] { cause?.StackTrace, base.StackTrace }.SelectMany(trace => (trace ?? "").Split('\n'))
            .Select(frame => frame.TrimEnd('\r')).Where(frame => frame.Contains(":line ", StringComparison.Ordinal)));
}

#if (en)
/// <summary>A report of what is left to write (<c>LabProgress</c>): a failure with its message only, no stack.</summary>
#else
/// <summary>Raport tego, co zostało do napisania (<c>LabProgress</c>): błąd z samym komunikatem, bez stosu.</summary>
#endif
internal sealed class ProgressReport(string message) : XunitException(message)
{
    public override string? StackTrace => null;
}
