using Microsoft.AspNetCore.Components.WebAssembly.Hosting;
using RayLab.Web;

// The playground is one page: no router, no HTTP client, so the trimmed site stays small.
WebAssemblyHostBuilder builder = WebAssemblyHostBuilder.CreateDefault(args);
builder.RootComponents.Add<Playground>("#app");
await builder.Build().RunAsync();
