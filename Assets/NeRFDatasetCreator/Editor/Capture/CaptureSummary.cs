using System.Globalization;

namespace NerfDatasetCreator.Editor
{
    /// <summary>Figures of a finished capture, for the log and the dataset's provenance (so runs can be compared).</summary>
    public sealed class CaptureSummary
    {
        public CaptureSummary(int views, double seconds, double viewsPerSecond, double verticalFieldOfViewDegrees,
            string renderPipeline, string colorSpace, bool asyncReadback, string unityVersion, string graphicsApi,
            int unsupportedRenderers)
        {
            Views = views;
            Seconds = seconds;
            ViewsPerSecond = viewsPerSecond;
            VerticalFieldOfViewDegrees = verticalFieldOfViewDegrees;
            RenderPipeline = renderPipeline;
            ColorSpace = colorSpace;
            AsyncReadback = asyncReadback;
            UnityVersion = unityVersion;
            GraphicsApi = graphicsApi;
            UnsupportedRenderers = unsupportedRenderers;
        }

        public int Views { get; }
        public double Seconds { get; }
        public double ViewsPerSecond { get; }
        public double VerticalFieldOfViewDegrees { get; }
        public string RenderPipeline { get; }
        public string ColorSpace { get; }
        public bool AsyncReadback { get; }
        public string UnityVersion { get; }
        public string GraphicsApi { get; }
        public int UnsupportedRenderers { get; }

        /// <summary>
        /// What the difference matting could not explain, summed over the capture's views (samples darker over white than
        /// over black; samples outside the geometry that differ from the clear colour): set by the dataset layer once its
        /// writers have finished (<see cref="ViewFileWriter.Matting"/>), default (no samples) for other consumers.
        /// </summary>
        public MattingDiagnostics Matting { get; internal set; }

        /// <summary>Issue 38: the shaders the material passes read exactly and the others; null without material passes.</summary>
        public MaterialShaderReport Materials { get; internal set; }

        public override string ToString() => string.Format(CultureInfo.InvariantCulture,
            "NeRF Dataset Creator: {0} views in {1:0.0} s ({2:0.00} views/s); {3}, {4} colour space, {5}, {6} readback, Unity {7}{8}",
            Views, Seconds, ViewsPerSecond, RenderPipeline, ColorSpace, GraphicsApi, AsyncReadback ? "async" : "ReadPixels",
            UnityVersion, UnsupportedRenderers == 0 ? "" : string.Format(CultureInfo.InvariantCulture,
                "; {0} non-mesh renderers left out of mask/depth/normal", UnsupportedRenderers))
            + (Matting.Samples > 0 ? "; matting: " + Matting : "");
    }
}
