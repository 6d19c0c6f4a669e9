using Xunit.Sdk;
using Xunit.v3;

[assembly: TestFramework(typeof(MyLab.Tests.StoppableRun))]

namespace MyLab.Tests;

#if (en)
/// <summary>
/// xUnit's own test framework, with one addition: a check can end the run (<see cref="Check.StopRun"/>). A check
/// calls it when your method ran past its time limit and cannot be stopped (its loop calls nothing of the checks'
/// code): .NET cannot end a thread, but the test process can end. The check's result is reported first; the checks
/// already running finish, no other check starts, and the test process ends with your loop in it, so no loop is left
/// keeping a processor busy. The checks not run are run by the next dotnet test (the grader runs them again itself).
/// </summary>
#else
/// <summary>
/// Zwykły mechanizm testów xUnit z jednym dodatkiem: sprawdzenie może zakończyć przebieg (<see cref="Check.StopRun"/>).
/// Sprawdzenie robi to, gdy Twoja metoda przekroczyła limit czasu i nie da się jej zatrzymać (jej pętla nie woła
/// niczego z kodu sprawdzeń): .NET nie potrafi zakończyć wątku, ale proces testów może się zakończyć. Najpierw jest
/// zgłoszony wynik sprawdzenia; sprawdzenia już trwające kończą się, żadne inne się nie zaczyna, a proces testów kończy
/// się razem z Twoją pętlą, więc żadna pętla nie zostaje, zajmując procesor. Sprawdzenia niewykonane wykona następne
/// dotnet test (oceniający wykonuje je ponownie sam).
/// </summary>
#endif
public sealed class StoppableRun : XunitTestFramework
{
    internal static readonly CancellationTokenSource Stop = new();

    protected override ITestFrameworkExecutor CreateExecutor(System.Reflection.Assembly assembly) => new Executor(base.CreateExecutor(assembly));

    private sealed class Executor(ITestFrameworkExecutor inner) : ITestFrameworkExecutor, IAsyncDisposable
    {
        public async ValueTask DisposeAsync()
        {
            switch (inner)
            {
                case IAsyncDisposable disposable:
                    await disposable.DisposeAsync();
                    break;
                case IDisposable disposable:
                    disposable.Dispose();
                    break;
            }
        }

        public async ValueTask RunTestCases(IReadOnlyCollection<ITestCase> testCases, IMessageSink executionMessageSink, ITestFrameworkExecutionOptions executionOptions, CancellationToken? cancellationToken)
        {
            using var run = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken ?? CancellationToken.None, Stop.Token);
            await inner.RunTestCases(testCases, executionMessageSink, executionOptions, run.Token);
        }
    }
}
