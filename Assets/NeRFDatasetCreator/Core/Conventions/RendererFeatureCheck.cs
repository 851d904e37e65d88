using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>One renderer feature of the URP renderer the capture camera renders with, as the Unity layer reads it.</summary>
    public sealed class RendererFeatureInfo
    {
        public RendererFeatureInfo(string name, IReadOnlyList<string> typeNames, bool active)
        {
            Name = name ?? "";
            TypeNames = typeNames ?? new string[0];
            Active = active;
        }

        /// <summary>The feature's name in the Renderer Data asset's list.</summary>
        public string Name { get; }

        /// <summary>Its type's name and its base types' names, most derived first (a subclass of a known feature is that feature).</summary>
        public IReadOnlyList<string> TypeNames { get; }

        /// <summary>The tick box in the list (<c>ScriptableRendererFeature.isActive</c>).</summary>
        public bool Active { get; }
    }

    /// <summary>
    /// Which URP renderer features may run in the capture's colour renders. The colour pass is rendered twice, over a
    /// black and over a white clear, and difference matting assumes the two differ by the clear colour only
    /// (pixels.md §2). A feature that draws over the whole image — URP's Full Screen Pass (a vignette, tint, outline,
    /// fog) — changes the background differently over black and over white: it veils the empty background (alpha ≠ 0)
    /// or makes covered pixels read as partly transparent. URP enqueues Full Screen Pass for every Game camera
    /// (URP 14.0.8 <c>Runtime/RendererFeatures/FullScreenPassRendererFeature.cs:80-89</c>, default injection point
    /// AfterRenderingPostProcessing, <c>:40</c>, which runs even with post-processing off; URP 17.0.3 skips only Preview
    /// and Reflection cameras, <c>:85-90</c>); the capture camera is a Game camera.
    /// </summary>
    public static class RendererFeatureCheck
    {
        /// <summary>
        /// URP's own features that write only where there is geometry, identically over either clear: SSAO (occlusion
        /// of rendered depth), Decal (projected onto rendered surfaces) and Screen Space Shadows (shadows on rendered
        /// surfaces). A user subclass of one of them counts as it.
        /// </summary>
        public static readonly IReadOnlyList<string> SafeTypeNames = new[] { "ScreenSpaceAmbientOcclusion", "DecalRendererFeature", "ScreenSpaceShadows" };

        /// <summary>URP's full-screen feature: refused over a transparent or solid background.</summary>
        public const string FullScreenPassTypeName = "FullScreenPassRendererFeature";

        /// <summary>
        /// Adds an error for every active Full Screen Pass (unless the background is the sky: one render, alpha 1
        /// everywhere, nothing to matte) and one warning naming every other active feature that is not known to be safe.
        /// Inactive features never run and are ignored.
        /// </summary>
        public static void Check(string rendererName, IEnumerable<RendererFeatureInfo> features, bool skyBackground,
            List<ValidationProblem> errors, List<ValidationProblem> warnings)
        {
            var unknown = new List<string>();
            foreach (var feature in features.Where(f => f.Active))
            {
                if (feature.TypeNames.Any(t => SafeTypeNames.Contains(t))) continue;
                if (feature.TypeNames.Contains(FullScreenPassTypeName))
                {
                    if (skyBackground) continue;
                    errors.Add(new ValidationProblem("renderer", rendererName + " ▸ " + feature.Name,
                        "is a Full Screen Pass renderer feature: it runs in both colour renders of every view (over black and over white) " +
                        "and changes the background differently in each, so the alpha of every image would be veiled or eaten away.",
                        "Untick \"" + feature.Name + "\" in the Renderer Features of " + rendererName + " while capturing, or make a renderer " +
                        "without it the pipeline asset's Default Renderer (the capture camera uses the default one)."));
                    continue;
                }
                unknown.Add("\"" + feature.Name + "\" (" + feature.TypeNames.FirstOrDefault() + ")");
            }
            if (unknown.Count > 0)
                warnings.Add(new ValidationProblem("renderer", rendererName,
                    "runs renderer features the capture does not know: " + string.Join(", ", unknown) + ". A feature that draws over " +
                    "the whole image (outline, fog, tint, vignette, pixelate) corrupts the alpha; one that draws only the scene's " +
                    "geometry is harmless. The capture's matting diagnostics report it if it did.",
                    "Untick them in the renderer's Renderer Features for the capture, or check the capture's \"Matting\" figures " +
                    "(dataset_config.json statistics) after a test run."));
        }
    }
}
