namespace NerfDatasetCreator
{
    /// <summary>The files a view can produce; encodings are defined in Documentation~/output-format.md.</summary>
    public enum DatasetFileKind
    {
        /// <summary>RGBA 8-bit sRGB PNG, straight alpha, transparent background: <c>r_7.png</c>.</summary>
        Color,
        /// <summary>16-bit grey PNG, z-depth in millimetres, 0 = no surface: <c>r_7_depth_0000.png</c>.</summary>
        DepthPng,
        /// <summary>Float32 single-channel EXR, z-depth in metres, 0 = no surface: <c>r_7_depth_0000.exr</c>.</summary>
        DepthExr,
        /// <summary>8-bit RGB PNG, n·0.5 + 0.5 in the output world frame, background 0: <c>r_7_normal_0000.png</c>.</summary>
        NormalPng,
        /// <summary>Float32 RGB EXR, unit normals in the output world frame, background 0: <c>r_7_normal_0000.exr</c>.</summary>
        NormalExr,
        /// <summary>8-bit grey PNG, 255 = target, 0 = background (coverage in between): <c>r_7_mask_0000.png</c>.</summary>
        MaskPng,
        /// <summary>16-bit grey PNG, the instance id of the object covering most of the pixel's samples, 0 = background: <c>r_7_instance_0000.png</c>.</summary>
        InstancePng,
        /// <summary>16-bit grey PNG, the class id of the class covering most of the pixel's samples, 0 = background or unclassed: <c>r_7_semantic_0000.png</c>.</summary>
        SemanticPng,
        /// <summary>The colour image without exposure and white balance (Documentation~/exposure.md), same encoding as <see cref="Color"/>: <c>r_7_clean.png</c>.</summary>
        CleanColor,
        /// <summary>Motion blur: the sharp RGBA image at the mid pose beside the blurred <c>r_7.png</c>: <c>r_7_sharp_0000.png</c>.</summary>
        SharpPng,
        /// <summary>Float32 RGBA EXR, linear colour with straight alpha before the clip to [0, 1] (settings <c>hdr</c>): <c>r_7_hdr.exr</c>.</summary>
        HdrExr,
        /// <summary>Material passes (settings <c>materials</c>, Documentation~/materials.md): the base colour as float32 RGBA EXR (linear, straight, A = the colour image's coverage) and as 8-bit sRGB RGBA PNG.</summary>
        AlbedoExr,
        AlbedoPng,
        /// <summary>Metallic: float32 RGBA EXR (R = G = B) and 8-bit RGBA PNG, linear (R = G = B = round(255·metallic)).</summary>
        MetallicExr,
        MetallicPng,
        /// <summary>Perceptual roughness (1 − smoothness), encoded as metallic.</summary>
        RoughnessExr,
        RoughnessPng,
        /// <summary>Specular colour (specular-setup shaders), encoded as albedo.</summary>
        SpecularExr,
        SpecularPng,
        /// <summary>Emission: float32 RGBA EXR, linear (may exceed 1), straight; no PNG.</summary>
        EmissionExr,
        /// <summary>8-bit grey PNG, 255 where the shader's parameters were read exactly, 0 elsewhere (edge coverage between): <c>r_7_material_coverage.png</c>.</summary>
        MaterialCoveragePng,
        /// <summary>
        /// Relighting: the view under each lighting condition, like <see cref="Color"/>: <c>r_7_light_sunset_090.png</c>.
        /// One file per condition key (<see cref="DatasetLayout.RelitRelativePath"/>); <see cref="DatasetLayout.Suffix"/> has none.
        /// </summary>
        RelitPng,
        /// <summary>Relighting with <c>hdr</c>: each condition's linear colour, like <see cref="HdrExr"/>: <c>r_7_light_sunset_090_hdr.exr</c>.</summary>
        RelitHdrExr,
    }
}
