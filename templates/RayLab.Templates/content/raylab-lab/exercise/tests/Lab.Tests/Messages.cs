using RayLab;
using RayLab.Grading;
using static MyLab.Tests.Check;
using ImageRgb24 = SixLabors.ImageSharp.PixelFormats.Rgb24;

namespace MyLab.Tests;

#if (en)
/// <summary>
/// Every display name and message of the checks, in one place: the checks call them by name. Numbers are written the
/// same on every machine (0.1, not 0,1).
/// </summary>
internal static class Msg
{
    // What every check shares (Check.cs)
    public const string TimeLimitPassed = "The check's time limit passed.";

    public const string OutsideYourCode = "outside your code";

    public static string PastLimit(double seconds, string last, bool stopped) =>
        F($"Time limit of {seconds:F0} s passed: the method did not finish (an endless loop?). Last: {last}. ")
        + (stopped ? "Your method was stopped."
            : $"Your method could not be stopped (its loop calls nothing of the checks' code), so dotnet test ends at this check, and the loop with it ({RunStopped}): the checks not yet started are not run. Fix the loop and run dotnet test again.");

    public static string NotWrittenYet(string what) => $"Not written yet: {what}";

    public static string YourCodeThrew(string type, string message, string context) => $"Your code threw {type}: {message} ({context})";

    public static string Time(double milliseconds) => F($"time: {milliseconds:F1} ms");

    public static string NoRayLabCamera(string type) => $"No RayLab camera for {type}.";

    // 2.1 Intensity (IntensityChecks.cs)
    public const string Constructors = "2.1 Intensity: constructors with 3, 2, 1 and 0 components, negative → 0";

    public const string Operators = "2.1 Intensity: +, −, × and ÷ a number, as RayLab's Intensity";

    public const string Printing = "2.1 Intensity: printing shows R, G and B";

    public const string ConstructorsAsRayLab = "5 constructors as RayLab's";

    public const string NegativeToZero = "negative → 0";

    public static string OperationsAsRayLab(int count) => F($"{count} operations as RayLab's");

    public static string PrintingMisses(string text, string part, string source) =>
        $"The lab: an intensity can be printed (operator <<). LightIntensity(0.25, 0.5, 0.75).ToString() gave \"{text}\", without {part} ({source}).";

    public static string IntensityShouldGive(string what, Intensity expected, LightIntensity actual, string at) =>
        $"2.1 Intensity: {what} should give {I(expected)} (each component on its own; negative → 0), got {I(actual)}{at}.";

    // 2.2 Image (ImageChecks.cs)
    public const string EightBitRule = "2.2 Image: the 8-bit rule i = int(256·I), cut not rounded, 0 … 255";

    public const string SetPixel = "2.2 Image: SetPixel writes the levels of an intensity into the bitmap, (x, y) with row 0 at the top";

    public static string EightBitLine(double intensity, byte actual, byte expected) =>
        F($"I = {intensity:R}: 256·I = {256 * intensity:R}, level {actual} (expected {expected})");

    public static string EightBitWrong(double intensity, byte expected, byte actual, string source) =>
        F($"2.2 Image: for I = {intensity:R} the rule i = int(256·I) gives {expected} (256·I = {256 * intensity:R}, cut; below 0 → 0, from 255/256 up → 255, NaN → 0), ToByte gave {actual} ({source}).");

    public static string ImageSize(int width, int height) => F($"2.2 Image: LabImage(3, 2) is {width}×{height}.");

    public static string SetPixelWrong(ImageRgb24 expected, ImageRgb24 set, string source) =>
        $"2.2 Image: after SetPixel(2, 0, (0.9, 0.2, 2)) the bitmap's pixel (2, 0) should hold {expected} (int(256·I), at most 255), it holds {set} ({source}).";

    public static string NewImageNotBlack(ImageRgb24 untouched) => $"2.2 Image: a new image is black, pixel (0, 1) holds {untouched}.";

    // 3 Camera, 3.1, 3.2 (CameraChecks.cs)
    public const string Frame = "3 Camera: the frame w = −g/|g|, u = (up × w)/|up × w|, v = w × u";

    public const string PixelCentre = "3 Camera: the pixel's place on the window, α = (x + sx)/nx, β = 1 − (y + sy)/ny";

    public const string OrthographicWindow = "3.1 Orthographic camera: the window, ViewHeight high, width from nx/ny";

    public const string OrthographicRays = "3.1 Orthographic camera: parallel rays through each pixel, as RayLab's (off-axis window, non-default up)";

    public const string PerspectiveWindow = "3.2 Perspective camera: the window from Fov and s, tan(Fov/2) = (v1 − v0)/(2 s)";

    public const string PerspectiveRays = "3.2 Perspective camera: the ray e + t (p − e) through each pixel, as RayLab's (off-axis window, non-default s and up)";

    public const string OrthographicSection = "3.1 Orthographic camera";

    public const string PerspectiveSection = "3.2 Perspective camera";

    public const string TaskPerspective = "the task's perspective camera";

    public const string DefaultPerspective = "the default (e = 0, looking at (0, 0, 1))";

    public const string OffAxisPerspective = "an off-axis window (0.1, −0.2)–(0.9, 0.4), s = 1.5";

    public const string TaskOrthographic = "the task's orthographic camera";

    public const string DefaultOrthographic = "the default (window [−1, 1])";

    public const string OffAxisOrthographic = "an off-axis window (0.5, −1)–(2.5, 0.5)";

    public const string PerspectiveFormula = "c = u0 u + v0 v − s w, p = e + c + α a + β b, the ray from e towards p − e";

    public const string OrthographicFormula = "p = e + c + α a + β b with c = u0 u + v0 v, the ray from p along −w";

    public static string FrameW(string camera) => $"3 Camera ({camera}): w = −g/|g| with g = Target − Position";

    public static string FrameU(string camera) => $"3 Camera ({camera}): u = (up × w)/|up × w| (without the lab's minus sign: u points right)";

    public static string FrameV(string camera) => $"3 Camera ({camera}): v = w × u";

    public static string ShouldBe(string what, Double3 expected, Double3 actual) => $"{what}: should be {V(expected)}, is {V(actual)}.";

    public static string AlphaWrong(int x, int y, double sx, double expected, double actual) =>
        F($"3 Camera: pixel ({x}, {y}) of 800, point sx = {sx}: α = (x + sx)/nx = {expected:R} (the pixel's centre is x + 0.5, not x), Alpha gave {actual:R}.");

    public static string BetaWrong(int x, int y, double sy, double expected, double actual) =>
        F($"3 Camera: pixel ({x}, {y}) of 600 rows, sy = {sy}: β = 1 − (y + sy)/ny = {expected:R} (row 0 at the top), Beta gave {actual:R}.");

    public static string PointsAsRayLab(int count) => F($"{count} points as RayLab's");

    public static string WindowWrong(string section, string camera, Window expected, Window actual) =>
        $"{section} ({camera}), 800×600: the window (u0, v0, u1, v1) should be {expected}, GetWindow gave {actual}.";

    public static string PixelPoint(int x, int y, double sx, double sy) => F($"pixel ({x}, {y}), point ({sx}, {sy})");

    public static string RayWrong(string section, string camera, string where, Double3 origin, Double3 direction, Double3 yourOrigin, Double3 yourDirection, string formula) =>
        $"{section} ({camera}), {where}: RayLab gives the ray from {V(origin)} along {V(direction)} (normalized), your camera from {V(yourOrigin)} along {V(yourDirection)}. The formula: {formula}.";

    public static string RaysAsRayLab(int count) => F($"{count} rays as RayLab's");

    // 4.1.1–4.1.4 Sampling (SamplingChecks.cs)
    public const string Regular = "4.1.1 Regular sampling: the k×k grid of cell centres, the same in every pixel";

    public const string Random = "4.1.2 Random sampling: uniform points in the pixel, different in each pixel";

    public const string Jittered = "4.1.3 Jittered sampling: exactly one random point in each cell of the k×k grid (stratification)";

    public const string Adaptive = "4.1.4 Adaptive sampling: the same rays and the same value in each pixel as RayLab's adaptive (the lab's rule and weights)";

    public const string BeforeFirstPixel = "before the first pixel";

    public static string RegularCount(int n, int count, string got) => F($"4.1.1 Regular sampling, n = {n}: there should be {n} points, there are {count}: {got}");

    public static string RegularPoint(int n, int pixel, double x, double y, double yourX, double yourY, string got) =>
        F($"4.1.1 Regular sampling, n = {n} ({Math.Sqrt(n)}×{Math.Sqrt(n)} grid), pixel {pixel}: the point ({x:F4}, {y:F4}) = ((i + 0.5)/k, (j + 0.5)/k) should be there, got ({yourX:F4}, {yourY:F4}). Your points: {got} …");

    public static string RegularAsRayLab(int n) => F($"n = {n}: the grid as RayLab's");

    public static string RandomCount(int n, int count) => F($"4.1.2 Random sampling: n = {n}, got {count} points.");

    public static string RandomLine(int pixels, int n, double chi2, double oracle, int different) =>
        F($"{pixels} pixels × {n}: χ² = {chi2:F1} (RayLab: {oracle:F1}; limit 37.7), {different} different first points");

    public static string RandomRepeats(int different, int pixels) =>
        F($"4.1.2 Random sampling: the first point repeats between pixels ({different} different in {pixels}): every pixel draws new points.");

    public static string RandomNotUniform(string cells, int uniform, double chi2, double oracle) =>
        F($"4.1.2 Random sampling: the points are not uniform in the pixel. The 16 cells hold {cells} points (uniform: {uniform}); χ² = {chi2:F1} > 37.7 (p = 0.001). RayLab: χ² = {oracle:F1}.");

    public static string JitteredCount(int n, int count) => F($"4.1.3 Jittered sampling: n = {n}, got {count} points.");

    public static string JitteredTwoInCell(int n, int k, int pixel, int i, int j, double x0, double y0, double x1, double y1) =>
        F($"4.1.3 Jittered sampling, n = {n}, {k}×{k} grid, pixel {pixel}: cell ({i}, {j}) holds two points, ({x0:F4}, {y0:F4}) and ({x1:F4}, {y1:F4}); the lab: one random point in each cell, ((i + rand())/k, (j + rand())/k).");

    public static string JitteredLine(int pixels, int n, double mean, double variance) =>
        F($"{pixels} pixels × {n}: one point in each cell; place in the cell: mean {mean:F3} (0.5), variance {variance:F4} (1/12 = 0.0833)");

    public static string JitteredNotUniform(double variance) =>
        F($"4.1.3 Jittered sampling: the point in a cell is not uniformly random — the variance of its place in the cell is {variance:F4}, for rand() it is 1/12 = 0.0833 (0 means: always the centre, as regular sampling).");

    public static string OutsideUnitSquare(string section, double x, double y, int pixel) =>
        F($"{section}: point ({x:R}, {y:R}) of pixel {pixel} lies outside the unit square [0, 1) × [0, 1).");

    public static string OffDepth3Grid(double x, double y) =>
        F($"the point ({x:R}, {y:R}) is off the 1/16-pixel grid, so in a square deeper than 3: the recursion does not stop at MaxDepth = 3");

    public static string TooManyRays(int calls) => F($"too many rays in one pixel ({calls}): the recursion does not stop at MaxDepth = 3");

    public static string AdaptiveWrong(string camera, int width, int height, int x, int y, int rays, string points, Intensity value, int yourRays, string yourPoints, LightIntensity yourValue) =>
        F($"4.1.4 Adaptive sampling ({camera}, {width}×{height}, depth 0–3, contrast 0.05), pixel ({x}, {y}): the lab's rule gives {rays} rays: {points}; value {I(value)}. Your method: {yourRays} rays: {yourPoints}; value {I(yourValue)}. The rule: a quadrant is split when its corner differs from the centre by more than the contrast; weights: square = ¼ Σ v(q), v(q) = (corner + centre)/2 or the split quadrant's value.");

    public static string AdaptiveLine(string camera, int width, int height, long rays, double perPixel, long oracleRays, int split) =>
        F($"{camera} {width}×{height}: {rays} rays ({perPixel:F2} per pixel), RayLab {oracleRays}; {split} pixels split");

    // 5 Task (TwoSpheresChecks.cs, Pictures.cs)
    public const string RenderLoop = "5 Task: the render loop, one ray through each pixel's centre, gives RayLab's picture";

    public const string SameSeedSamePicture = "5 Task: the same picture on every run (a random sampler with the same seed)";

    public const string TwoSpheres = "5 Task: two spheres with your camera and your adaptive sampling, close to the exact image (RMSE, FLIP)";

    public const string NoPixelYet = "no pixel yet";

    public static string Pixel(long x, long y) => F($"pixel ({x}, {y})");

    public static string Figures(double rmse, int max, double flip) => F($"RMSE {rmse:F3} levels, max {max}, FLIP {flip:F4}");

    public static string RenderLoopLine(string camera, int width, int height, long rays, double milliseconds, int differ, string figures) =>
        F($"{camera} {width}×{height}: {rays} rays, {milliseconds:F1} ms, {differ} pixels unlike RayLab's; against the exact image: {figures}");

    public static string RenderLoopRays(int expected, long rays) => F($"5 Task: one point per pixel makes {expected} rays, the loop returned {rays}.");

    public static string RenderLoopPicture(string camera, int differ, int x, int y, RayLab.Rgb24 theirs, RayLab.Rgb24 yours) =>
        F($"5 Task ({camera}): the render loop should give RayLab's picture (the same rays, colour from Scene.Trace, the mean, SetPixel). {differ} pixels differ; the first ({x}, {y}): RayLab {theirs}, your loop {yours}.");

    public static string SameSeedLine(int width, int height, int differ) => F($"{width}×{height}, 4 random samples per pixel, twice: {differ} pixels differ");

    public static string SameSeedPicture(int differ, int x, int y, RayLab.Rgb24 first, RayLab.Rgb24 second) =>
        F($"5 Task: the same seed should give the same picture at any thread count (one Random per row, from the seed and the row). {differ} pixels differ; the first ({x}, {y}): {first}, then {second}.");

    public static string TwoSpheresLine(string camera, int width, int height, long rays, double perPixel, double milliseconds, string figures) =>
        F($"{camera} {width}×{height}: {rays} rays ({perPixel:F2} per pixel), {milliseconds:F1} ms; against the exact image: {figures}");

    public static string TwoSpheresOracleLine(long rays, string figures) => F($"RayLab (the same adaptive): {rays} rays (corners shared by neighbouring pixels): {figures}");

    public static string TwoSpheresTooFar(string camera, string figures, string oracleFigures, double rmse, double flip) =>
        F($"5 Task ({camera}): the two-sphere picture is too far from the exact one: {figures}; RayLab's adaptive at the same settings: {oracleFigures}; allowed RMSE ≤ {rmse:F3}, FLIP ≤ {flip:F4}. See the checks of 3.x and 4.1.4 first.");

    // The lab's progress (LabProgress.cs)
    public const string PartsWrittenName = "The lab: which parts are written";

    public static string PartsWritten(int written, int total) => F($"{written} of {total} parts written");

    public static string StillToWrite(string counted, string list, string id, string title, string file) =>
        $"{counted}; still to write:\n{list}\nNext: {id} {title}, src/Lab/{file}.cs (its checks are skipped while it throws NotImplementedException).";

    // Your own code (UsesChecks.cs)
    public const string OwnCode = "Your own code: the section uses only what the lab allows";

    public static string Finding(UseFinding finding) => finding.Message(polish: false);

    public static string NothingOffTheList(string section) => $"section {section}: nothing off the list";
}
#else
/// <summary>
/// Wszystkie nazwy i komunikaty sprawdzeń w jednym miejscu: sprawdzenia wołają je po nazwie. Liczby są zapisane tak
/// samo na każdym komputerze (0.1, a nie 0,1).
/// </summary>
internal static class Msg
{
    // Co mają wspólnego wszystkie sprawdzenia (Check.cs)
    public const string TimeLimitPassed = "Przekroczony limit czasu sprawdzenia.";

    public const string OutsideYourCode = "poza Twoim kodem";

    public static string PastLimit(double seconds, string last, bool stopped) =>
        F($"Przekroczony limit czasu {seconds:F0} s: metoda się nie skończyła (zapętlenie?). Ostatnio: {last}. ")
        + (stopped ? "Twoja metoda została zatrzymana."
            : $"Twojej metody nie dało się zatrzymać (jej pętla nie woła niczego z kodu sprawdzeń), więc dotnet test kończy się na tym sprawdzeniu razem z nią ({RunStopped}): sprawdzenia, które się jeszcze nie zaczęły, nie są wykonane. Popraw pętlę i uruchom dotnet test ponownie.");

    public static string NotWrittenYet(string what) => $"Jeszcze nie napisane: {what}";

    public static string YourCodeThrew(string type, string message, string context) => $"Twój kod rzucił {type}: {message} ({context})";

    public static string Time(double milliseconds) => F($"czas: {milliseconds:F1} ms");

    public static string NoRayLabCamera(string type) => $"Brak kamery RayLab dla {type}.";

    // 2.1 Natężenie (IntensityChecks.cs)
    public const string Constructors = "2.1 Natężenie: konstruktory z 3, 2, 1 i 0 składowymi, ujemne → 0";

    public const string Operators = "2.1 Natężenie: +, −, × i ÷ przez skalar, jak Intensity z RayLab";

    public const string Printing = "2.1 Natężenie: wypisanie pokazuje R, G i B";

    public const string ConstructorsAsRayLab = "5 konstruktorów jak w RayLab";

    public const string NegativeToZero = "ujemne → 0";

    public static string OperationsAsRayLab(int count) => F($"{count} działań jak w RayLab");

    public static string PrintingMisses(string text, string part, string source) =>
        $"Instrukcja: natężenie da się wypisać (operator <<). LightIntensity(0.25, 0.5, 0.75).ToString() dało \"{text}\", bez {part} ({source}).";

    public static string IntensityShouldGive(string what, Intensity expected, LightIntensity actual, string at) =>
        $"2.1 Natężenie: {what} powinno dać {I(expected)} (każda składowa osobno; ujemna → 0), a dało {I(actual)}{at}.";

    // 2.2 Obraz (ImageChecks.cs)
    public const string EightBitRule = "2.2 Obraz: reguła 8-bitowa i = int(256·I), obcięcie, a nie zaokrąglenie, 0 … 255";

    public const string SetPixel = "2.2 Obraz: SetPixel zapisuje poziomy natężenia do bitmapy, (x, y), wiersz 0 na górze";

    public static string EightBitLine(double intensity, byte actual, byte expected) =>
        F($"I = {intensity:R}: 256·I = {256 * intensity:R}, poziom {actual} (oczekiwany {expected})");

    public static string EightBitWrong(double intensity, byte expected, byte actual, string source) =>
        F($"2.2 Obraz: dla I = {intensity:R} reguła i = int(256·I) daje {expected} (256·I = {256 * intensity:R}, obcięte; poniżej 0 → 0, od 255/256 w górę → 255, NaN → 0), a ToByte dało {actual} ({source}).");

    public static string ImageSize(int width, int height) => F($"2.2 Obraz: LabImage(3, 2) ma rozmiar {width}×{height}.");

    public static string SetPixelWrong(ImageRgb24 expected, ImageRgb24 set, string source) =>
        $"2.2 Obraz: po SetPixel(2, 0, (0.9, 0.2, 2)) piksel (2, 0) bitmapy powinien mieć poziomy {expected} (int(256·I), najwyżej 255), a ma {set} ({source}).";

    public static string NewImageNotBlack(ImageRgb24 untouched) => $"2.2 Obraz: nowy obraz jest czarny, a piksel (0, 1) ma {untouched}.";

    // 3 Kamera, 3.1, 3.2 (CameraChecks.cs)
    public const string Frame = "3 Kamera: baza w = −g/|g|, u = (up × w)/|up × w|, v = w × u";

    public const string PixelCentre = "3 Kamera: położenie piksela na oknie, α = (x + sx)/nx, β = 1 − (y + sy)/ny";

    public const string OrthographicWindow = "3.1 Kamera ortogonalna: okno o wysokości ViewHeight, szerokość z nx/ny";

    public const string OrthographicRays = "3.1 Kamera ortogonalna: równoległe promienie przez każdy piksel, jak w RayLab (okno niewyśrodkowane, inne up)";

    public const string PerspectiveWindow = "3.2 Kamera perspektywiczna: okno z Fov i s, tg(Fov/2) = (v1 − v0)/(2 s)";

    public const string PerspectiveRays = "3.2 Kamera perspektywiczna: promień e + t (p − e) przez każdy piksel, jak w RayLab (okno niewyśrodkowane, inne s i up)";

    public const string OrthographicSection = "3.1 Kamera ortogonalna";

    public const string PerspectiveSection = "3.2 Kamera perspektywiczna";

    public const string TaskPerspective = "perspektywiczna z zadania";

    public const string DefaultPerspective = "domyślna (e = 0, patrzy na (0, 0, 1))";

    public const string OffAxisPerspective = "okno niewyśrodkowane (0.1, −0.2)–(0.9, 0.4), s = 1.5";

    public const string TaskOrthographic = "ortogonalna z zadania";

    public const string DefaultOrthographic = "domyślna (okno [−1, 1])";

    public const string OffAxisOrthographic = "okno niewyśrodkowane (0.5, −1)–(2.5, 0.5)";

    public const string PerspectiveFormula = "c = u0 u + v0 v − s w, p = e + c + α a + β b, promień z e w kierunku p − e";

    public const string OrthographicFormula = "p = e + c + α a + β b z c = u0 u + v0 v, promień z p w kierunku −w";

    public static string FrameW(string camera) => $"3 Kamera ({camera}): w = −g/|g| z g = Target − Position";

    public static string FrameU(string camera) => $"3 Kamera ({camera}): u = (up × w)/|up × w| (bez minusa z instrukcji: u wskazuje w prawo)";

    public static string FrameV(string camera) => $"3 Kamera ({camera}): v = w × u";

    public static string ShouldBe(string what, Double3 expected, Double3 actual) => $"{what}: powinno być {V(expected)}, a jest {V(actual)}.";

    public static string AlphaWrong(int x, int y, double sx, double expected, double actual) =>
        F($"3 Kamera: piksel ({x}, {y}) z 800 kolumn, sx = {sx}: α = (x + sx)/nx = {expected:R} (środek piksela to x + 0.5, nie x), a Alpha dało {actual:R}.");

    public static string BetaWrong(int x, int y, double sy, double expected, double actual) =>
        F($"3 Kamera: piksel ({x}, {y}) z 600 wierszy, sy = {sy}: β = 1 − (y + sy)/ny = {expected:R} (wiersz 0 na górze), a Beta dało {actual:R}.");

    public static string PointsAsRayLab(int count) => F($"{count} punktów jak w RayLab");

    public static string WindowWrong(string section, string camera, Window expected, Window actual) =>
        $"{section} ({camera}), 800×600: okno (u0, v0, u1, v1) powinno być {expected}, a GetWindow dało {actual}.";

    public static string PixelPoint(int x, int y, double sx, double sy) => F($"piksel ({x}, {y}), punkt ({sx}, {sy})");

    public static string RayWrong(string section, string camera, string where, Double3 origin, Double3 direction, Double3 yourOrigin, Double3 yourDirection, string formula) =>
        $"{section} ({camera}), {where}: RayLab daje promień z {V(origin)} w kierunku {V(direction)} (znormalizowany), a Twoja kamera z {V(yourOrigin)} w kierunku {V(yourDirection)}. Wzór: {formula}.";

    public static string RaysAsRayLab(int count) => F($"{count} promieni jak w RayLab");

    // 4.1.1–4.1.4 Próbkowanie (SamplingChecks.cs)
    public const string Regular = "4.1.1 Próbkowanie regularne: siatka k×k środków komórek, ta sama w każdym pikselu";

    public const string Random = "4.1.2 Próbkowanie losowe: punkty równomiernie w pikselu, inne w każdym pikselu";

    public const string Jittered = "4.1.3 Próbkowanie jittered: dokładnie jeden losowy punkt w każdej komórce siatki k×k (stratyfikacja)";

    public const string Adaptive = "4.1.4 Próbkowanie adaptacyjne: te same promienie i ta sama wartość w każdym pikselu co adaptacyjne RayLab (reguła i wagi z instrukcji)";

    public const string BeforeFirstPixel = "przed pierwszym pikselem";

    public static string RegularCount(int n, int count, string got) => F($"4.1.1 Próbkowanie regularne, n = {n}: powinno być {n} punktów, jest {count}: {got}");

    public static string RegularPoint(int n, int pixel, double x, double y, double yourX, double yourY, string got) =>
        F($"4.1.1 Próbkowanie regularne, n = {n} (siatka {Math.Sqrt(n)}×{Math.Sqrt(n)}), piksel {pixel}: powinien być punkt ({x:F4}, {y:F4}) = ((i + 0.5)/k, (j + 0.5)/k), a jest ({yourX:F4}, {yourY:F4}). Twoje punkty: {got} …");

    public static string RegularAsRayLab(int n) => F($"n = {n}: siatka jak w RayLab");

    public static string RandomCount(int n, int count) => F($"4.1.2 Próbkowanie losowe: n = {n}, a punktów jest {count}.");

    public static string RandomLine(int pixels, int n, double chi2, double oracle, int different) =>
        F($"{pixels} pikseli × {n}: χ² = {chi2:F1} (RayLab: {oracle:F1}; próg 37.7), {different} różnych pierwszych punktów");

    public static string RandomRepeats(int different, int pixels) =>
        F($"4.1.2 Próbkowanie losowe: pierwszy punkt powtarza się między pikselami ({different} różnych na {pixels}): każdy piksel losuje nowe punkty.");

    public static string RandomNotUniform(string cells, int uniform, double chi2, double oracle) =>
        F($"4.1.2 Próbkowanie losowe: punkty nie są równomierne w pikselu. W 16 komórkach siatki 4×4 jest {cells} punktów (równo: {uniform}); χ² = {chi2:F1} > 37.7 (p = 0.001). RayLab: χ² = {oracle:F1}.");

    public static string JitteredCount(int n, int count) => F($"4.1.3 Próbkowanie jittered: n = {n}, a punktów jest {count}.");

    public static string JitteredTwoInCell(int n, int k, int pixel, int i, int j, double x0, double y0, double x1, double y1) =>
        F($"4.1.3 Próbkowanie jittered, n = {n}, siatka {k}×{k}, piksel {pixel}: w komórce ({i}, {j}) są dwa punkty, ({x0:F4}, {y0:F4}) i ({x1:F4}, {y1:F4}); instrukcja: jeden losowy punkt w każdej komórce, ((i + rand())/k, (j + rand())/k).");

    public static string JitteredLine(int pixels, int n, double mean, double variance) =>
        F($"{pixels} pikseli × {n}: po jednym punkcie w każdej komórce; położenie w komórce: średnia {mean:F3} (0.5), wariancja {variance:F4} (1/12 = 0.0833)");

    public static string JitteredNotUniform(double variance) =>
        F($"4.1.3 Próbkowanie jittered: punkt nie jest losowany równomiernie w komórce — wariancja położenia w komórce {variance:F4}, a dla rand() to 1/12 = 0.0833 (0 znaczy: zawsze środek, jak w próbkowaniu regularnym).");

    public static string OutsideUnitSquare(string section, double x, double y, int pixel) =>
        F($"{section}: punkt ({x:R}, {y:R}) piksela {pixel} leży poza kwadratem jednostkowym [0, 1) × [0, 1).");

    public static string OffDepth3Grid(double x, double y) =>
        F($"punkt ({x:R}, {y:R}) leży poza siatką co 1/16 piksela, więc w kwadracie głębszym niż 3: rekurencja nie zatrzymuje się na MaxDepth = 3");

    public static string TooManyRays(int calls) => F($"za dużo promieni w jednym pikselu ({calls}): rekurencja nie zatrzymuje się na MaxDepth = 3");

    public static string AdaptiveWrong(string camera, int width, int height, int x, int y, int rays, string points, Intensity value, int yourRays, string yourPoints, LightIntensity yourValue) =>
        F($"4.1.4 Próbkowanie adaptacyjne ({camera}, {width}×{height}, głębokość 0–3, kontrast 0.05), piksel ({x}, {y}): instrukcja daje {rays} promieni: {points}; wartość {I(value)}. Twoja metoda: {yourRays} promieni: {yourPoints}; wartość {I(yourValue)}. Reguła: podobszar dzielony, gdy jego róg różni się od środka o więcej niż kontrast; wagi: kwadrat = ¼ Σ v(q), v(q) = (róg + środek)/2 albo wartość podzielonego podobszaru.");

    public static string AdaptiveLine(string camera, int width, int height, long rays, double perPixel, long oracleRays, int split) =>
        F($"{camera} {width}×{height}: {rays} promieni ({perPixel:F2} na piksel), RayLab {oracleRays}; {split} pikseli podzielonych");

    // 5 Zadanie (TwoSpheresChecks.cs, Pictures.cs)
    public const string RenderLoop = "5 Zadanie: pętla renderowania, jeden promień przez środek piksela, daje obraz RayLab";

    public const string SameSeedSamePicture = "5 Zadanie: ten sam obraz przy każdym uruchomieniu (losowe próbki z tym samym ziarnem)";

    public const string TwoSpheres = "5 Zadanie: dwie kule Twoją kamerą i Twoim próbkowaniem adaptacyjnym, blisko dokładnego obrazu (RMSE, FLIP)";

    public const string NoPixelYet = "żaden piksel";

    public static string Pixel(long x, long y) => F($"piksel ({x}, {y})");

    public static string Figures(double rmse, int max, double flip) => F($"RMSE {rmse:F3} poziomu, max {max}, FLIP {flip:F4}");

    public static string RenderLoopLine(string camera, int width, int height, long rays, double milliseconds, int differ, string figures) =>
        F($"{camera} {width}×{height}: {rays} promieni, {milliseconds:F1} ms, {differ} pikseli innych niż w RayLab; względem dokładnego obrazu: {figures}");

    public static string RenderLoopRays(int expected, long rays) => F($"5 Zadanie: jeden punkt na piksel daje {expected} promieni, a pętla zwróciła {rays}.");

    public static string RenderLoopPicture(string camera, int differ, int x, int y, RayLab.Rgb24 theirs, RayLab.Rgb24 yours) =>
        F($"5 Zadanie ({camera}): pętla renderowania powinna dać obraz RayLab (te same promienie, kolor z Scene.Trace, średnia, SetPixel). {differ} pikseli się różni; pierwszy ({x}, {y}): RayLab {theirs}, Twoja pętla {yours}.");

    public static string SameSeedLine(int width, int height, int differ) => F($"{width}×{height}, 4 próbki losowe na piksel, dwa razy: {differ} pikseli różnych");

    public static string SameSeedPicture(int differ, int x, int y, RayLab.Rgb24 first, RayLab.Rgb24 second) =>
        F($"5 Zadanie: to samo ziarno powinno dać ten sam obraz przy dowolnej liczbie wątków (jeden generator Random na wiersz, z ziarna i numeru wiersza). {differ} pikseli się różni; pierwszy ({x}, {y}): {first}, potem {second}.");

    public static string TwoSpheresLine(string camera, int width, int height, long rays, double perPixel, double milliseconds, string figures) =>
        F($"{camera} {width}×{height}: {rays} promieni ({perPixel:F2} na piksel), {milliseconds:F1} ms; względem dokładnego obrazu: {figures}");

    public static string TwoSpheresOracleLine(long rays, string figures) => F($"RayLab (to samo adaptacyjne): {rays} promieni (rogi wspólne dla sąsiednich pikseli): {figures}");

    public static string TwoSpheresTooFar(string camera, string figures, string oracleFigures, double rmse, double flip) =>
        F($"5 Zadanie ({camera}): obraz dwóch kul jest za daleko od dokładnego: {figures}; próbkowanie adaptacyjne RayLab z tymi samymi ustawieniami: {oracleFigures}; dopuszczalne RMSE ≤ {rmse:F3}, FLIP ≤ {flip:F4}. Zobacz najpierw sprawdzenia 3.x i 4.1.4.");

    // Postęp laboratorium (LabProgress.cs)
    public const string PartsWrittenName = "Laboratorium: które części są napisane";

    public static string PartsWritten(int written, int total) => F($"{written} z {total} części napisane");

    public static string StillToWrite(string counted, string list, string id, string title, string file) =>
        $"{counted}; jeszcze do napisania:\n{list}\nNastępna: {id} {title}, src/Lab/{file}.cs (jej testy są pominięte, dopóki rzuca NotImplementedException).";

    // Twój własny kod (UsesChecks.cs)
    public const string OwnCode = "Twój własny kod: sekcja używa tylko tego, na co laboratorium pozwala";

    public static string Finding(UseFinding finding) => finding.Message(polish: true);

    public static string NothingOffTheList(string section) => $"sekcja {section}: nic spoza listy";
}
#endif
