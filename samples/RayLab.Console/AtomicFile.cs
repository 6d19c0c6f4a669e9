namespace RayLab.Cli;

/// <summary>Writes a text file under a temporary name and renames it, so a failure leaves no partial file.</summary>
internal static class AtomicFile
{
    public static void WriteAllText(string path, string text)
    {
        string full = Path.GetFullPath(path);
        string temp = Path.Combine(Path.GetDirectoryName(full)!, $".{Path.GetFileName(full)}.{Guid.NewGuid():N}.tmp");
        try
        {
            File.WriteAllText(temp, text);
            File.Move(temp, full, overwrite: true);
        }
        catch
        {
            if (File.Exists(temp))
            {
                File.Delete(temp); // when the folder itself is gone, deleting would throw and hide the real error
            }

            throw;
        }
    }
}
