namespace RayLab;

/// <summary>Which loop renders the pixels of a point-sampled image (see <see cref="Renderer.Kernel"/>).</summary>
public enum RenderKernel
{
    /// <summary>The widest SIMD packet the hardware runs natively, or <see cref="Scalar"/> when it has none or the scene needs double precision.</summary>
    Auto,

    /// <summary>One ray at a time in double precision: the reference path, as a student writes it.</summary>
    Scalar,

    /// <summary>Packets of 4 pixels (SSE, Arm NEON).</summary>
    Vector128,

    /// <summary>Packets of 8 pixels (AVX2).</summary>
    Vector256,

    /// <summary>Packets of 16 pixels (AVX-512).</summary>
    Vector512,
}
