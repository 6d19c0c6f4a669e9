namespace RayLab.Simd;

/// <summary>
/// Marks a method written for <c>Vector128</c> in a partial type: the build's source generator
/// (src/RayLab.Generators, EveryWidthGenerator) adds its <c>Vector256</c> and <c>Vector512</c> overloads, the same
/// text with the register type renamed, so that a formula every lane width needs is written once.
/// </summary>
[AttributeUsage(AttributeTargets.Method, Inherited = false)]
internal sealed class EveryWidthAttribute : Attribute;
