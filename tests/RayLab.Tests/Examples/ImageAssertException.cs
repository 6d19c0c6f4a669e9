namespace RayLab.Tests.Examples;

/// <summary>An <see cref="ImageAssert"/> that failed; the message says where and by how much.</summary>
/// <param name="message">What differs: the pixel, the expected and actual levels, how many pixels.</param>
public sealed class ImageAssertException(string message) : Exception(message);
