using RayLab.Reports.Patterns;
using RayLab.Sampling;

namespace RayLab.Reports.Tests.Patterns;

public class PowerSpectrumTests
{
    [Fact]
    public void Jittered_is_low_near_zero_frequency_where_random_is_flat()
    {
        PowerSpectrum random = PowerSpectrum.Measure(new RandomSampler(64, 1), realisations: 1024, maxFrequency: 16);
        PowerSpectrum jittered = PowerSpectrum.Measure(new JitteredSampler(64, 1), realisations: 1024, maxFrequency: 16);

        for (int r = 1; r <= 16; r++)
        {
            // White noise: every ring's mean power is 1 (the average of 1024 periodograms: within a few per cent).
            Assert.InRange(random.RadialMean[r], 0.85, 1.15);
        }

        // Stratified: the cells' points cannot bunch up, so the low frequencies carry little power. Theory for
        // n×n jittered along an axis: P(u) = 1 − sinc²(u/n), 0.05 at u = 1 and 0.19 at u = 2 for n = 8.
        Assert.True(jittered.RadialMean[1] < 0.1, $"ring 1: {jittered.RadialMean[1]}");
        Assert.True(jittered.RadialMean[2] < 0.3, $"ring 2: {jittered.RadialMean[2]}");
        Assert.True(jittered.RadialMean[1] < random.RadialMean[1] / 8);

        Assert.Equal(64, random.RadialMean[0], 1e-9); // the DC term is N
    }

    [Fact]
    public void A_direction_free_pattern_is_isotropic_and_the_grid_is_not()
    {
        PowerSpectrum random = PowerSpectrum.Measure(new RandomSampler(16, 2), realisations: 1024, maxFrequency: 8);
        PowerSpectrum grid = PowerSpectrum.Measure(new RegularSampler(16), realisations: 16, maxFrequency: 8);

        // About 10·log10(1/1024) = −30 dB for white noise; the grid's ring at |f| = 4 holds its peaks (power N at (±4, 0), (0, ±4)).
        Assert.InRange(random.AnisotropyDecibels[4], -33, -26);
        Assert.True(grid.AnisotropyDecibels[4] > 0, $"grid: {grid.AnisotropyDecibels[4]} dB");
        Assert.Equal(16, grid.Power(4, 0), 1e-9);
        Assert.Equal(0, grid.Power(1, 0), 1e-9);
    }

    [Fact]
    public void The_spectrum_does_not_depend_on_the_thread_count()
    {
        var sampler = new JitteredSampler(16, 4);
        PowerSpectrum one = PowerSpectrum.Measure(sampler, 200, 6, maxDegreeOfParallelism: 1);
        PowerSpectrum many = PowerSpectrum.Measure(sampler, 200, 6, maxDegreeOfParallelism: 4);

        Assert.Equal(one.RadialMean, many.RadialMean);
        Assert.Equal(one.AnisotropyDecibels, many.AnisotropyDecibels);
    }
}
