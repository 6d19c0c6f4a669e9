namespace RayLab.Geometry;

/// <summary>Where a sphere lies between the camera's near and far planes (the camera image plane's test, one margin for every renderer).</summary>
internal enum SphereVisibility
{
    /// <summary>Wholly nearer than the near plane or farther than the far plane: never visible.</summary>
    Hidden,

    /// <summary>Cut by the near or far plane (within the margin of one): its picture has an edge there.</summary>
    Clipped,

    /// <summary>Wholly between the planes.</summary>
    Whole,
}
