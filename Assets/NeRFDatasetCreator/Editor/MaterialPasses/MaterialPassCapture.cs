using System;
using System.Collections.Generic;
using UnityEngine;
using UnityEngine.Experimental.Rendering;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Renders and reads back one view's material passes (issue 38). Built-in: NerfMaterial.shader's replacement passes,
    /// drawn outside the camera like the data passes. URP: one camera render per pass with the Rendering Debugger's
    /// material mode set (<see cref="IUrpMaterialDebugView"/>: lighting and post-processing off), over a (0,0,0,0) solid
    /// clear. In both, the coverage pass says which samples a supported shader covers; every value elsewhere is 0.
    /// Targets: <see cref="CaptureEnvironment.ColorFormat"/> (half float, no sRGB: the colour pass's own format, which
    /// URP renders into without an 8-bit intermediate) and R8G8B8A8_UNorm for the coverage, no MSAA, no mips.
    /// Read back synchronously with ReadPixels into CPU textures of the same format, like <see cref="SynchronousReadback"/>.
    /// </summary>
    public sealed class MaterialPassCapture : IDisposable
    {
        readonly MaterialPipeline _pipeline;
        readonly MaterialPassKind[] _passes;
        readonly int _width, _height;
        readonly bool _gamma;
        MaterialPassRenderer _renderer;
        RenderTexture _values, _coverage;
        Texture2D _valuesCpu, _coverageCpu;
        // Reused per view: only the result arrays handed to the writers are new (they outlive the view's render).
        ushort[] _valuesBuffer;
        byte[] _coverageBuffer;

        /// <param name="renderers">The capture's copies (as the data passes get them).</param>
        /// <param name="passes">The passes to render: albedo, metallic, smoothness (→ roughness), specular, emission.</param>
        public MaterialPassCapture(IEnumerable<Renderer> renderers, int cullingMask, IReadOnlyList<MaterialPassKind> passes, int width, int height)
        {
            _pipeline = CurrentPipeline();
            if (_pipeline == MaterialPipeline.Urp && UrpMaterialDebug.View == null)
                throw new CaptureException("The material passes need the Universal Render Pipeline's Rendering Debugger, but the " +
                    "package's URP assembly is not loaded (URP 14–17 must be installed). Turn \"materials\" off or install URP 14 or later.");
            _passes = new List<MaterialPassKind>(passes).ToArray();
            _width = width;
            _height = height;
            // Gamma projects: the shaders work on gamma-space colours, which the passes decode with the sRGB curve.
            _gamma = QualitySettings.activeColorSpace == ColorSpace.Gamma;
            try
            {
                _renderer = new MaterialPassRenderer(renderers, cullingMask, _pipeline);
                _values = Create(CaptureEnvironment.ColorFormat, "NeRF material pass");
                _coverage = Create(CaptureEnvironment.LabelFormat, "NeRF material coverage");
            }
            catch
            {
                Dispose();
                throw;
            }
        }

        /// <summary>URP when the active pipeline asset is URP's (by its type name, as CaptureEnvironment names it), else Built-in.</summary>
        public static MaterialPipeline CurrentPipeline() =>
            CaptureEnvironment.RenderPipelineName == "UniversalRenderPipelineAsset" ? MaterialPipeline.Urp : MaterialPipeline.BuiltIn;

        public MaterialPipeline Pipeline => _pipeline;

        /// <summary>Shaders read exactly so far.</summary>
        public IReadOnlyCollection<string> SupportedShaders => _renderer.Materials.SupportedShaders;

        /// <summary>Every other shader seen so far, by name, with the reason.</summary>
        public IReadOnlyDictionary<string, string> UnsupportedShaders => _renderer.Materials.UnsupportedShaders;

        /// <summary>Renders the passes of the camera's current view and returns their values.</summary>
        public MaterialPassResult Render(Camera camera)
        {
            var previous = RenderTexture.active;
            try
            {
                _renderer.PrepareView();
                _renderer.Render(camera, _coverage, MaterialPassRenderer.CoveragePass);
                var coverage = _coverageBuffer ?? (_coverageBuffer = new byte[4 * _width * _height]);
                Read(_coverage, ref _coverageCpu).GetRawTextureData<byte>().CopyTo(coverage);
                var result = new MaterialPassResult { Supported = new byte[_width * _height] };
                for (var i = 0; i < result.Supported.Length; i++) result.Supported[i] = coverage[4 * i] >= 128 ? (byte)255 : (byte)0;
                if (_pipeline == MaterialPipeline.Urp)
                {
                    using (UrpMaterialDebug.View.Begin())
                        foreach (var pass in _passes) Store(result, pass, RenderUrp(camera, pass), coverage);
                }
                else
                {
                    foreach (var pass in _passes)
                    {
                        _renderer.Render(camera, _values, (int)pass);
                        Store(result, pass, ReadValues(), coverage);
                    }
                }
                return result;
            }
            finally
            {
                RenderTexture.active = previous;
            }
        }

        /// <summary>One camera render in the pass's Rendering Debugger mode, over a transparent black solid clear; the camera's state is restored.</summary>
        ushort[] RenderUrp(Camera camera, MaterialPassKind pass)
        {
            var clearFlags = camera.clearFlags;
            var background = camera.backgroundColor;
            var target = camera.targetTexture;
            try
            {
                UrpMaterialDebug.View.Show(pass);
                camera.clearFlags = CameraClearFlags.SolidColor;
                camera.backgroundColor = new Color(0f, 0f, 0f, 0f);
                camera.targetTexture = _values;
                camera.Render();
            }
            finally
            {
                camera.clearFlags = clearFlags;
                camera.backgroundColor = background;
                camera.targetTexture = target;
            }
            return ReadValues();
        }

        ushort[] ReadValues()
        {
            var values = _valuesBuffer ?? (_valuesBuffer = new ushort[4 * _width * _height]);
            Read(_values, ref _valuesCpu).GetRawTextureData<ushort>().CopyTo(values);
            return values;
        }

        /// <summary>The pass's half-float RGBA as the result's linear floats, 0 where unsupported (<see cref="MaterialValues"/>).</summary>
        void Store(MaterialPassResult result, MaterialPassKind pass, ushort[] rgba, byte[] coverage)
        {
            switch (pass)
            {
                case MaterialPassKind.Albedo: result.Albedo = MaterialValues.Colour(rgba, coverage, _gamma, specularSetupOnly: false); break;
                case MaterialPassKind.Specular: result.Specular = MaterialValues.Colour(rgba, coverage, _gamma, specularSetupOnly: true); break;
                case MaterialPassKind.Emission: result.Emission = MaterialValues.Colour(rgba, coverage, _gamma, specularSetupOnly: false); break;
                case MaterialPassKind.Metallic: result.Metallic = MaterialValues.Scalar(rgba, coverage, roughness: false); break;
                case MaterialPassKind.Smoothness: result.Roughness = MaterialValues.Scalar(rgba, coverage, roughness: true); break;
            }
        }

        RenderTexture Create(GraphicsFormat format, string name)
        {
            var descriptor = new RenderTextureDescriptor(_width, _height, format, 24) { useMipMap = false, autoGenerateMips = false, msaaSamples = 1 };
            var texture = new RenderTexture(descriptor) { name = name, hideFlags = HideFlags.HideAndDontSave };
            if (!texture.Create())
            {
                Object.DestroyImmediate(texture);
                throw new CaptureException("Unity could not create the " + _width + "×" + _height + " " + format + " render texture '" +
                    name + "' (out of GPU memory?). Lower the resolution or the supersampling, or turn \"materials\" off.");
            }
            return texture;
        }

        static Texture2D Read(RenderTexture source, ref Texture2D cpu)
        {
            if (cpu == null)
            {
                if (!CaptureEnvironment.CanReadPixels(source.graphicsFormat))
                    throw new CaptureException("This GPU cannot read back " + source.graphicsFormat + " (" + source.name + "). Turn \"materials\" off or capture on another machine.");
                cpu = new Texture2D(source.width, source.height, source.graphicsFormat, TextureCreationFlags.None) { name = source.name + " readback", hideFlags = HideFlags.HideAndDontSave };
            }
            RenderTexture.active = source;
            cpu.ReadPixels(new Rect(0, 0, source.width, source.height), 0, 0, false);
            return cpu;
        }

        public void Dispose()
        {
            _renderer?.Dispose();
            _renderer = null;
            foreach (var texture in new[] { _values, _coverage })
            {
                if (texture == null) continue;
                if (RenderTexture.active == texture) RenderTexture.active = null;
                texture.Release();
                Object.DestroyImmediate(texture);
            }
            _values = _coverage = null;
            foreach (var cpu in new[] { _valuesCpu, _coverageCpu })
                if (cpu != null) Object.DestroyImmediate(cpu);
            _valuesCpu = _coverageCpu = null;
        }
    }
}
