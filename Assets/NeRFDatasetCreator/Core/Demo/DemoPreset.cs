using System;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What <c>nerf-dataset demo --preset</c> adds to the plain demo scene: nothing (a static object capture with RGBA,
    /// depth, normals and masks), or one feature of the capture — moving content, labels, a lens, exposure, motion blur, one camera moving in time, HDR, flow.
    /// </summary>
    public enum DemoPreset
    {
        Static,
        Dynamic,
        Labels,
        Lens,
        Exposure,
        Blur,

        /// <summary>One camera moving around the target over time (monocular dynamic, depth on): a SLAM sequence's source.</summary>
        Monocular,
        Hdr,

        /// <summary>Every material pass (albedo, metallic, roughness, specular, emission) beside each view (<see cref="AnalyticMaterials"/>).</summary>
        Materials,
        /// <summary>Relighting: the views under an analytic sky at three rotations and one point light, with lights/ (issue 38).</summary>
        Relight,
        /// <summary>The monocular preset with the geometry pack at every step and flow/ (optical and scene flow, occlusion, tracks).</summary>
        Flow,
    }

    /// <summary>The presets' command-line names, in <see cref="DemoPreset"/> order.</summary>
    public static class DemoPresets
    {
        public static readonly string[] Names = { "static", "dynamic", "labels", "lens", "exposure", "blur", "monocular", "hdr", "materials", "relight", "flow" };

        public static string Name(DemoPreset preset) => Names[(int)preset];

        /// <summary>The preset named <paramref name="value"/> (any case), or null with a problem naming the choices.</summary>
        public static DemoPreset? Parse(string value, out ValidationProblem problem)
        {
            var index = Array.FindIndex(Names, n => string.Equals(n, value?.Trim(), StringComparison.OrdinalIgnoreCase));
            problem = index >= 0 ? null
                : new ValidationProblem("--preset", value ?? "", "is not a demo preset.", "Use one of: " + string.Join(", ", Names.Select(n => n)) + "." + SpellingSuggestion.Sentence(value, Names));
            return index >= 0 ? (DemoPreset?)index : null;
        }
    }
}
