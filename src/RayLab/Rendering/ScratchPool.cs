namespace RayLab.Rendering;

/// <summary>
/// Working space a <see cref="Renderer"/> keeps from one render to the next: each thread of a render rents a scratch
/// and gives it back when its rows are done, so a renderer that draws frame after frame allocates its per-thread
/// buffers once. Thread-safe (two renders may share it); it keeps at most <see cref="Capacity"/> items.
/// </summary>
internal sealed class ScratchPool
{
    /// <summary>The most items kept: more than any render has threads at once.</summary>
    public const int Capacity = 64;

    private readonly Lock _gate = new();
    private readonly List<object> _free = [];

    /// <summary>A kept <typeparamref name="T"/>, the one given back last, or a new one.</summary>
    public T Rent<T>()
        where T : class, new()
    {
        lock (_gate)
        {
            for (int i = _free.Count - 1; i >= 0; i--)
            {
                if (_free[i] is T kept)
                {
                    _free.RemoveAt(i);
                    return kept;
                }
            }
        }

        return new T();
    }

    /// <summary>Keeps <paramref name="item"/> for a later <see cref="Rent{T}"/>.</summary>
    public void Return(object item)
    {
        lock (_gate)
        {
            if (_free.Count < Capacity)
            {
                _free.Add(item);
            }
        }
    }
}
