using Microsoft.AspNetCore.Components.WebAssembly.Hosting;
using RayLab.Web;
using RayLab.Web.Lab;

// The picture the URL asks for comes first, before Blazor starts the page's controls (Lab/FirstPicture.cs).
if (OperatingSystem.IsBrowser())
{
    await FirstPicture.RenderAsync();
}

// The playground is one page: no router, no HTTP client, so the trimmed site stays small.
WebAssemblyHostBuilder builder = WebAssemblyHostBuilder.CreateDefault(args);
builder.RootComponents.Add<Playground>("#app");
await builder.Build().RunAsync();
