using System.Collections.Generic;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The capture's worker-thread writer for datasets: wraps a view's readback arrays as Core's raw frames (no copy),
    /// marks its normals as Unity world normals (the encoders relabel them into the output world as they read them), and
    /// hands them to Core's <see cref="ViewPipeline"/>, which runs the per-view stages in their order (lens, blur/sharp,
    /// exposure, ids, encoding). The consumer releases the view afterwards.
    /// </summary>
    sealed class DatasetViewWriter : IViewWriter
    {
        readonly IReadOnlyList<PlannedView> _views;
        readonly ViewPipeline _pipeline;

        /// <param name="views">The planned views in the order their poses were given to the capture.</param>
        public DatasetViewWriter(IReadOnlyList<PlannedView> views, ViewPipeline pipeline)
        {
            _views = views;
            _pipeline = pipeline;
        }

        public void Write(CapturedView view)
        {
            var colour = new RawFrame(view.Width, view.Height, view.Supersampling)
            {
                ColorOverBlack = view.ColorOverBlack,
                ColorOverWhite = view.ColorOverWhite,
                ColorIsGammaEncoded = view.ColorIsGammaEncoded,
                Mask = view.Mask,
                MaskBytesPerPixel = 1,
            };
            var atOutputSize = view.DataWidth != view.Width || view.DataHeight != view.Height;
            var data = atOutputSize ? new RawFrame(view.DataWidth, view.DataHeight, 1) : colour;
            data.Depth = view.Depth;
            data.Normals = view.Normal;
            // The normal pass writes Unity world normals; the encoders relabel them as they read them.
            data.NormalsInUnityWorld = true;
            if (view.Labels != null) colour.InstanceIds = LabelsPassIds.InstanceIds(view.Labels);
            if (view.Materials != null)
            {
                colour.MaterialAlbedo = view.Materials.Albedo;
                colour.MaterialMetallic = view.Materials.Metallic;
                colour.MaterialRoughness = view.Materials.Roughness;
                colour.MaterialSpecular = view.Materials.Specular;
                colour.MaterialEmission = view.Materials.Emission;
                colour.MaterialSupported = view.Materials.Supported;
            }
            if (view.Relit != null)
            {
                // Each condition's colour pair goes through the same colour pipeline as the plain image (RawFrame.Relit).
                colour.Relit = new Dictionary<string, RawFrame>(System.StringComparer.Ordinal);
                foreach (var pair in view.Relit)
                    colour.Relit[pair.Key] = new RawFrame(view.Width, view.Height, view.Supersampling)
                    {
                        ColorOverBlack = pair.Value[0],
                        ColorOverWhite = pair.Value[1],
                        ColorIsGammaEncoded = view.ColorIsGammaEncoded,
                    };
            }
            // Motion blur: the sub-frame average beside the mid-pose render, with the same mask, ids and (at the colour's
            // size) depth and normals.
            RawFrame blurred = null;
            if (view.BlurredOverBlack != null)
            {
                blurred = new RawFrame(view.Width, view.Height, view.Supersampling)
                {
                    ColorOverBlack = view.BlurredOverBlack,
                    ColorOverWhite = view.BlurredOverWhite,
                    ColorIsGammaEncoded = view.ColorIsGammaEncoded,
                    Mask = view.Mask,
                    MaskBytesPerPixel = 1,
                    InstanceIds = colour.InstanceIds,
                };
                if (!atOutputSize)
                {
                    blurred.Depth = data.Depth;
                    blurred.Normals = data.Normals;
                    blurred.NormalsInUnityWorld = true;
                    data = blurred;
                }
            }
            _pipeline.Write(_views[view.ViewIndex], colour, data, blurred);
        }
    }
}
