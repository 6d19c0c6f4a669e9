namespace RayLab.Cameras;

/// <summary>
/// Work compiled once per camera projection: <see cref="ImagePlane.Dispatch{TAction, TResult}"/> calls
/// <see cref="Run{TP}"/> with the plane's own projection type, so a renderer never chooses between orthographic
/// and perspective itself.
/// </summary>
/// <typeparam name="TResult">What the work returns.</typeparam>
internal interface IProjectionAction<TResult>
{
    /// <summary>Does the work for the plane's projection <typeparamref name="TP"/>.</summary>
    /// <param name="plane">The image plane, typed with its projection.</param>
    TResult Run<TP>(ImagePlane<TP> plane)
        where TP : struct, IProjection;
}
