using System;
using UnityEngine;
using UnityEngine.Experimental.Rendering;
using UnityEngine.Rendering;

namespace NerfDatasetCreator.Editor
{
    /// <summary>Facts about this editor that decide whether and how a capture can render.</summary>
    public static class CaptureEnvironment
    {
        /// <summary>True when Unity runs without a graphics device (<c>-nographics</c>): nothing can be rendered.</summary>
        public static bool HasNoGraphicsDevice => SystemInfo.graphicsDeviceType == GraphicsDeviceType.Null;

        /// <summary>"Built-in" or the active render pipeline asset's type name (quality level first, then graphics settings).</summary>
        public static string RenderPipelineName
        {
            get
            {
                var asset = GraphicsSettings.currentRenderPipeline;
                return asset == null ? "Built-in" : asset.GetType().Name;
            }
        }

        /// <summary>
        /// HDRP is recognised by its asset's type name (HDRenderPipelineAsset), so that no HDRP assembly is referenced.
        /// Its exposure and tonemapping would change the colours and its passes ignore our untagged aux shaders.
        /// </summary>
        public static bool IsHdrp
        {
            get
            {
                var asset = GraphicsSettings.currentRenderPipeline;
                for (var type = asset == null ? null : asset.GetType(); type != null; type = type.BaseType)
                    if (type.Name.IndexOf("HDRenderPipelineAsset", StringComparison.Ordinal) >= 0) return true;
                return false;
            }
        }

        /// <summary>
        /// The colour pass's format: 16-bit float RGBA, rendered twice per view (over black and over white) for difference
        /// matting (Core's DifferenceMatting). A float format has no sRGB variant, so the GPU stores what the shaders
        /// write, unencoded: linear light in a Linear project, gamma-space values in a Gamma one
        /// (<c>RenderTextureDescriptor(w, h, GraphicsFormat, depth)</c> sets its sRGB flag from the format alone, UCR
        /// <c>Runtime/Export/Graphics/Texture.cs</c>; URP 14 renders into the target's own descriptor when it needs an
        /// intermediate, <c>UniversalRenderPipelineCore.cs:1365</c>). Half precision (step 2⁻¹¹ below 1) keeps alpha within
        /// 0.3 of an 8-bit step; it is also URP's own HDR format, blendable on every desktop GPU.
        /// </summary>
        public const GraphicsFormat ColorFormat = GraphicsFormat.R16G16B16A16_SFloat;

        public const GraphicsFormat DepthFormat = GraphicsFormat.R32_SFloat;
        public const GraphicsFormat NormalFormat = GraphicsFormat.R32G32B32A32_SFloat;

        /// <summary>
        /// The labels pass's format: 8-bit UNORM RGBA holding two 16-bit ids as bytes (<see cref="CapturePasses.Labels"/>).
        /// Not an _SRGB format, so the GPU stores the bytes the shader writes with no encoding; every GPU renders to it and
        /// reads it back (the mask's own fallback format).
        /// </summary>
        public const GraphicsFormat LabelFormat = GraphicsFormat.R8G8B8A8_UNorm;

        /// <summary>R8_UNorm where it can be rendered to (1 byte per sample), else RGBA8 (the red channel is read).</summary>
        public static GraphicsFormat MaskFormat =>
            CanRenderTo(GraphicsFormat.R8_UNorm) ? GraphicsFormat.R8_UNorm : GraphicsFormat.R8G8B8A8_UNorm;

        public static bool CanRenderTo(GraphicsFormat format)
        {
#if UNITY_2023_2_OR_NEWER
            return SystemInfo.IsFormatSupported(format, GraphicsFormatUsage.Render);
#else
            return SystemInfo.IsFormatSupported(format, FormatUsage.Render);
#endif
        }

        /// <summary>Whether transparent content can be alpha-blended into <paramref name="format"/>.</summary>
        public static bool CanBlend(GraphicsFormat format)
        {
#if UNITY_2023_2_OR_NEWER
            return SystemInfo.IsFormatSupported(format, GraphicsFormatUsage.Blend);
#else
            return SystemInfo.IsFormatSupported(format, FormatUsage.Blend);
#endif
        }

        public static bool CanReadPixels(GraphicsFormat format)
        {
#if UNITY_2023_2_OR_NEWER
            return SystemInfo.IsFormatSupported(format, GraphicsFormatUsage.ReadPixels);
#else
            return SystemInfo.IsFormatSupported(format, FormatUsage.ReadPixels);
#endif
        }

        /// <summary>
        /// URP's Render Scale (the public <c>renderScale</c> property of UniversalRenderPipelineAsset, read by name so no
        /// URP assembly is referenced), or null for the Built-in pipeline and pipelines without one. URP ignores
        /// differences below 0.05 from 1 (kRenderScaleThreshold in UniversalRenderPipeline.cs).
        /// </summary>
        public static float? PipelineRenderScale
        {
            get
            {
                var asset = GraphicsSettings.currentRenderPipeline;
                var property = asset == null ? null : asset.GetType().GetProperty("renderScale",
                    System.Reflection.BindingFlags.Public | System.Reflection.BindingFlags.Instance);
                if (property == null || property.PropertyType != typeof(float) || !property.CanRead) return null;
                return (float)property.GetValue(asset);
            }
        }

        /// <summary>Throws a <see cref="CaptureException"/> saying why this editor cannot render a capture, if it cannot.</summary>
        public static void ThrowIfCannotRender(CapturePasses passes)
        {
            if (HasNoGraphicsDevice)
                throw new CaptureException(
                    "Unity has no graphics device (it was started with -nographics), so nothing can be rendered. " +
                    "Run the capture without -nographics; in batch mode keep -batchmode and, on a machine without a display, " +
                    "start Unity under a virtual display such as xvfb-run.");
            if (IsHdrp)
                throw new CaptureException(
                    "The project uses the High Definition Render Pipeline (" + RenderPipelineName + "), which this version " +
                    "does not support: its exposure and tonemapping would alter the colours and the depth, normal and mask " +
                    "passes. Capture in a Built-in or Universal Render Pipeline project.");
            var scale = PipelineRenderScale;
            if (scale.HasValue && Math.Abs(scale.Value - 1f) >= 0.05f)
                throw new CaptureException(
                    "The render pipeline asset (" + RenderPipelineName + ") has Render Scale " +
                    scale.Value.ToString("0.##", System.Globalization.CultureInfo.InvariantCulture) + ". URP would then render " +
                    "at another resolution and rescale into the capture's textures, blurring the colour and blending depth " +
                    "and normals across edges. Set Render Scale to 1 in the asset (Quality settings may select another " +
                    "asset per level), then capture.");
            Require(ColorFormat, "colour", passes, CapturePasses.Color);
            if ((passes & CapturePasses.Color) != 0 && !CanBlend(ColorFormat))
                throw new CaptureException(
                    "This GPU (" + SystemInfo.graphicsDeviceName + ", " + SystemInfo.graphicsDeviceType + ") cannot blend into " +
                    ColorFormat + ", the format of the colour pass, so transparent objects would render wrong. Capture on another machine.");
            Require(MaskFormat, "mask", passes, CapturePasses.Mask);
            Require(DepthFormat, "depth", passes, CapturePasses.Depth);
            Require(NormalFormat, "normal", passes, CapturePasses.Normal);
            Require(LabelFormat, "labels", passes, CapturePasses.Labels);
        }

        static void Require(GraphicsFormat format, string pass, CapturePasses passes, CapturePasses needing)
        {
            if ((passes & needing) == 0 || CanRenderTo(format)) return;
            throw new CaptureException(
                "This GPU (" + SystemInfo.graphicsDeviceName + ", " + SystemInfo.graphicsDeviceType + ") cannot render to " +
                format + ", the format of the " + pass + " pass. Turn the " + pass + " pass off or capture on another machine.");
        }
    }
}
