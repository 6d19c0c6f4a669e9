using System.Runtime.InteropServices.JavaScript;
using System.Runtime.Versioning;

namespace RayLab.Web.Lab;

/// <summary>
/// The page's language in the browser: the html <c>lang</c>, which index.html's script sets before .NET starts (the
/// session's choice, else Polish for a browser language <c>pl</c> or <c>pl-…</c>, else English), and the switch's
/// choice, kept for the browser tab's session. Calls js/raylab.js, which <see cref="FirstPicture"/> imports first.
/// </summary>
[SupportedOSPlatform("browser")]
internal static partial class PageLanguage
{
    /// <summary>The html <c>lang</c>: <c>pl</c> or <c>en</c>.</summary>
    [JSImport("language", "raylab")]
    public static partial string Get();

    /// <summary>Sets the html <c>lang</c>, the window's title and the session's choice.</summary>
    /// <param name="lang"><c>pl</c> or <c>en</c>.</param>
    /// <param name="title">The window's title in that language.</param>
    [JSImport("setLanguage", "raylab")]
    public static partial void Set(string lang, string title);
}
