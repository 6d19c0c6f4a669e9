using System.Diagnostics;
using System.Net;
using System.Net.Sockets;

namespace RayLab.Web.Tests;

/// <summary>
/// The published playground, served on 127.0.0.1 by a small static server in the test process: each file with its MIME
/// type, and the pre-compressed <c>.br</c> (or <c>.gz</c>) copy that <c>dotnet publish</c> writes beside it when the
/// browser accepts it, as a static host such as GitHub Pages or nginx with brotli_static does.
/// </summary>
public sealed class StaticSite : IAsyncLifetime
{
    private static readonly Dictionary<string, string> Types = new(StringComparer.OrdinalIgnoreCase)
    {
        [".html"] = "text/html; charset=utf-8",
        [".js"] = "text/javascript",
        [".mjs"] = "text/javascript",
        [".css"] = "text/css",
        [".json"] = "application/json",
        [".wasm"] = "application/wasm",
        [".dll"] = "application/octet-stream",
        [".dat"] = "application/octet-stream",
        [".pdb"] = "application/octet-stream",
        [".png"] = "image/png",
        [".svg"] = "image/svg+xml",
        [".ico"] = "image/x-icon",
    };

    private HttpListener? _listener;
    private Task? _serving;
    private string? _published;

    /// <summary>The published folder's wwwroot.</summary>
    public string Root { get; private set; } = "";

    /// <summary>The site's address, ending in a slash.</summary>
    public string Address { get; private set; } = "";

    /// <summary>How the site was obtained, and in how long (printed with the figures).</summary>
    public string PublishNote { get; private set; } = "";

    /// <summary>The repository's root (the folder holding RayLab.sln).</summary>
    public static string RepositoryRoot
    {
        get
        {
            string? dir = AppContext.BaseDirectory;
            while (dir is not null && !File.Exists(Path.Combine(dir, "RayLab.sln")))
            {
                dir = Path.GetDirectoryName(dir);
            }

            return dir ?? throw new InvalidOperationException("RayLab.sln not found above " + AppContext.BaseDirectory);
        }
    }

    public async ValueTask InitializeAsync()
    {
        string? given = Environment.GetEnvironmentVariable("RAYLAB_WEB_SITE");
        string site;
        if (!string.IsNullOrEmpty(given))
        {
            site = given;
            PublishNote = $"site from RAYLAB_WEB_SITE={given}";
        }
        else
        {
            site = Path.Combine(Path.GetTempPath(), "raylab-web-" + Guid.NewGuid().ToString("N")[..8]);
            _published = site;
            var clock = Stopwatch.StartNew();
            await Publish(site);
            PublishNote = $"dotnet publish samples/RayLab.Web -c Release -o {site}: {clock.Elapsed.TotalSeconds:0} s";
        }

        Root = Directory.Exists(Path.Combine(site, "wwwroot")) ? Path.Combine(site, "wwwroot") : site;
        Assert.True(File.Exists(Path.Combine(Root, "index.html")), $"no index.html in {Root}");
        int port = FreePort();
        Address = $"http://127.0.0.1:{port}/";
        _listener = new HttpListener();
        _listener.Prefixes.Add(Address);
        _listener.Start();
        _serving = Task.Run(Serve);
    }

    private static async Task Publish(string output)
    {
        var start = new ProcessStartInfo("dotnet", ["publish", Path.Combine(RepositoryRoot, "samples", "RayLab.Web"), "-c", "Release", "-o", output])
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
        };
        using Process process = Process.Start(start)!;
        Task<string> stdout = process.StandardOutput.ReadToEndAsync();
        Task<string> stderr = process.StandardError.ReadToEndAsync();
        await process.WaitForExitAsync();
        Assert.True(process.ExitCode == 0, $"dotnet publish failed:\n{await stdout}\n{await stderr}");
    }

    private static int FreePort()
    {
        using var probe = new TcpListener(IPAddress.Loopback, 0);
        probe.Start();
        return ((IPEndPoint)probe.LocalEndpoint).Port;
    }

    private async Task Serve()
    {
        while (_listener is { IsListening: true })
        {
            HttpListenerContext context;
            try
            {
                context = await _listener.GetContextAsync();
            }
            catch (Exception e) when (e is HttpListenerException or ObjectDisposedException or InvalidOperationException)
            {
                return;
            }

            _ = Task.Run(() => Answer(context));
        }
    }

    private void Answer(HttpListenerContext context)
    {
        HttpListenerResponse response = context.Response;
        try
        {
            string path = Uri.UnescapeDataString(context.Request.Url!.AbsolutePath).TrimStart('/');
            string file = Path.GetFullPath(Path.Combine(Root, path.Length == 0 ? "index.html" : path));
            if (!file.StartsWith(Root, StringComparison.Ordinal) || !File.Exists(file))
            {
                response.StatusCode = 404;
                return;
            }

            response.ContentType = Types.GetValueOrDefault(Path.GetExtension(file), "application/octet-stream");
            response.Headers["Cache-Control"] = "no-cache";
            string accept = context.Request.Headers["Accept-Encoding"] ?? "";
            string served = file;
            if (accept.Contains("br", StringComparison.Ordinal) && File.Exists(file + ".br"))
            {
                served = file + ".br";
                response.Headers["Content-Encoding"] = "br";
            }
            else if (accept.Contains("gzip", StringComparison.Ordinal) && File.Exists(file + ".gz"))
            {
                served = file + ".gz";
                response.Headers["Content-Encoding"] = "gzip";
            }

            byte[] bytes = File.ReadAllBytes(served);
            response.ContentLength64 = bytes.Length;
            response.OutputStream.Write(bytes);
        }
        finally
        {
            response.Close();
        }
    }

    /// <summary>What the browser downloads with brotli: each file's .br copy where there is one, else the file.</summary>
    public long BrotliBytes() => Directory.EnumerateFiles(Root, "*", SearchOption.AllDirectories)
        .Where(f => !f.EndsWith(".br", StringComparison.Ordinal) && !f.EndsWith(".gz", StringComparison.Ordinal))
        .Sum(f => new FileInfo(File.Exists(f + ".br") ? f + ".br" : f).Length);

    public async ValueTask DisposeAsync()
    {
        _listener?.Stop();
        _listener?.Close();
        if (_serving is not null)
        {
            await _serving;
        }

        // The folder this fixture published into is its own; a site given by RAYLAB_WEB_SITE is left alone.
        if (_published is not null && Directory.Exists(_published))
        {
            Directory.Delete(_published, recursive: true);
        }
    }
}
