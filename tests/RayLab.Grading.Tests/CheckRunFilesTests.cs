using RayLab.Tests.Shared;

namespace RayLab.Grading.Tests;

public sealed class CheckRunFilesTests : IDisposable
{
    private readonly TempDirectory _dir = new();

    public void Dispose() => _dir.Dispose();

    [Fact]
    public void ATrxGivesEachChecksDisplayNameOutcomeAndFirstMessageLine()
    {
        string trx = _dir.File("checks.trx");
        File.WriteAllText(trx, """
            <?xml version="1.0" encoding="utf-8"?>
            <TestRun xmlns="http://microsoft.com/schemas/VisualStudio/TeamTest/2010">
              <Results>
                <UnitTestResult testName="2.1 Natężenie: dodawanie" outcome="Passed" />
                <UnitTestResult testName="2.2 Obraz: ToByte(0.1)" outcome="Failed">
                  <Output><ErrorInfo><Message>

                    dla I = 0.1 reguła daje 25, a ToByte dało 26
                    druga linia</Message></ErrorInfo></Output>
                </UnitTestResult>
                <UnitTestResult testName="3.1 Kamera ortogonalna" outcome="NotExecuted" />
                <UnitTestResult testName="5 Zadanie" />
              </Results>
            </TestRun>
            """);
        Assert.Equal(
            [
                new CheckResult("2.1 Natężenie: dodawanie", "Passed", null),
                new CheckResult("2.2 Obraz: ToByte(0.1)", "Failed", "dla I = 0.1 reguła daje 25, a ToByte dało 26"),
                new CheckResult("3.1 Kamera ortogonalna", "NotExecuted", null),
                new CheckResult("5 Zadanie", "Failed", null),
            ],
            CheckRunFiles.Results(trx));
        Assert.Equal(["Passed", "Failed", "Skipped", "Failed"], CheckRunFiles.Results(trx).Select(r => r.Result));
    }

    [Fact]
    public void ABlameSequenceGivesTheChecksStartedAndNotFinished()
    {
        string sequence = _dir.File("Sequence_1.xml");
        File.WriteAllText(sequence, """
            <?xml version="1.0"?>
            <TestSequence>
              <Test Name="MyLab.Tests.SamplingChecks.Regular" DisplayName="4.1.1 Regularne" Completed="False" />
              <Test Name="MyLab.Tests.SamplingChecks.Random" DisplayName="4.1.2 Losowe" Completed="True" />
              <Test Name="MyLab.Tests.ImageChecks.Save" Completed="False" />
            </TestSequence>
            """);
        Assert.Equal(
            [new UnfinishedCheck("MyLab.Tests.SamplingChecks.Regular", "4.1.1 Regularne"), new UnfinishedCheck("MyLab.Tests.ImageChecks.Save", "MyLab.Tests.ImageChecks.Save")],
            CheckRunFiles.Unfinished(sequence));
    }

    [Fact]
    public void AFileThatIsMissingALinkNotXmlOrWithADtdHoldsNothing()
    {
        string outside = _dir.File("outside.trx");
        File.WriteAllText(outside, """<TestRun><Results><UnitTestResult testName="2.1 x" outcome="Passed" /></Results></TestRun>""");
        Assert.Single(CheckRunFiles.Results(outside));
        string link = _dir.File("link.trx");
        File.CreateSymbolicLink(link, outside);
        Assert.Empty(CheckRunFiles.Results(link));
        Assert.Empty(CheckRunFiles.Results(_dir.File("missing.trx")));
        string broken = _dir.File("broken.trx");
        File.WriteAllText(broken, "<TestRun><Results>");
        Assert.Empty(CheckRunFiles.Results(broken));
        string entities = _dir.File("entities.trx");
        File.WriteAllText(entities, """<?xml version="1.0"?><!DOCTYPE r [<!ENTITY a "aaaaaaaaaa">]><TestRun><Results><UnitTestResult testName="&a;" outcome="Passed" /></Results></TestRun>""");
        Assert.Empty(CheckRunFiles.Results(entities));
    }

    [Fact]
    public void AFileLargerThanTheCapHoldsNothing()
    {
        string big = _dir.File("big.trx");
        using (var stream = File.Create(big))
        {
            stream.Write("""<TestRun><Results><UnitTestResult testName="2.1 x" outcome="Passed" /></Results></TestRun>"""u8);
            stream.SetLength(CheckRunFiles.MaxBytes + 1);
        }

        Assert.Empty(CheckRunFiles.Results(big));
    }
}
