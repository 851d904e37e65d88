using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Whether a template camera's culling mask (bit i set = layer i drawn, Unity's Camera.cullingMask) leaves out layers
    /// that the target's renderers are on: those renderers would be missing from every image, with nothing else to say so.
    /// </summary>
    public static class CullingMaskCheck
    {
        /// <summary>
        /// Null when every layer in <paramref name="rendererLayers"/> (one entry per renderer) is drawn; else an error when
        /// no renderer would be drawn at all, a warning (<paramref name="isError"/> false) when only some would be missing.
        /// <paramref name="layerName"/> gives a layer's name for the message.
        /// </summary>
        public static ValidationProblem Check(int cullingMask, IReadOnlyList<int> rendererLayers, System.Func<int, string> layerName,
            string camera, out bool isError)
        {
            isError = false;
            var hidden = rendererLayers.Where(l => (cullingMask & (1 << l)) == 0).ToList();
            if (hidden.Count == 0) return null;
            isError = hidden.Count == rendererLayers.Count;
            var names = string.Join(", ", hidden.Distinct().OrderBy(l => l).Select(l =>
            {
                var name = layerName?.Invoke(l);
                return (string.IsNullOrEmpty(name) ? "layer" : "'" + name + "'") + " (" + l.ToString(CultureInfo.InvariantCulture) + ")";
            }));
            var count = hidden.Count.ToString(CultureInfo.InvariantCulture) + " of the target's " +
                        rendererLayers.Count.ToString(CultureInfo.InvariantCulture) + " renderers";
            return new ValidationProblem("camera.copyFromCamera", camera,
                isError
                    ? "culls every layer the target's renderers are on (" + names + "): every image would be empty."
                    : "culls " + names + ", so " + count + " would be missing from every image.",
                "Add those layers to the template camera's Culling Mask, or move the renderers to a layer it draws.");
        }
    }
}
