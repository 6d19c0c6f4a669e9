namespace RayLab;

/// <summary>
/// A render cannot draw this scene, and says which sphere and why instead of drawing a wrong picture: a sphere that
/// reaches too far from the camera for double (every method), or one the exact reference (<see cref="RenderMethod.Exact"/>)
/// cannot outline exactly. <see cref="Exception.Message"/> names the sphere (by its index in
/// <see cref="Scene.Spheres"/>); <see cref="Reason"/> is the same text without the name, for messages that
/// name the sphere their own way (a scene file's <c>spheres[1]</c>).
/// </summary>
public sealed class UnsupportedSceneException : ArgumentException
{
    /// <summary>Creates the exception.</summary>
    /// <param name="sphereIndex">The sphere's index in the scene.</param>
    /// <param name="reason">What is wrong with it, as a phrase that follows "Sphere N".</param>
    public UnsupportedSceneException(int sphereIndex, string reason)
        : base($"Sphere {sphereIndex} {reason}", "scene")
    {
        SphereIndex = sphereIndex;
        Reason = reason;
    }

    /// <summary>The index of the sphere in <see cref="Scene.Spheres"/>.</summary>
    public int SphereIndex { get; }

    /// <summary>What is wrong with the sphere.</summary>
    public string Reason { get; }
}
