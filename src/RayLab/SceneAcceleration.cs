namespace RayLab;

/// <summary>How a <see cref="Scene"/> finds the sphere a ray hits (the lab's reference [5], space subdivision).</summary>
public enum SceneAcceleration
{
    /// <summary>The hierarchy from a few spheres on (where it pays, measured), every sphere tested below that.</summary>
    Auto,

    /// <summary>Every sphere tested for every ray (the lab's loop).</summary>
    None,

    /// <summary>Always through the bounding volume hierarchy.</summary>
    Hierarchy,
}
