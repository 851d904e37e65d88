using System;
using System.Collections.Generic;
using UnityEngine;
using UnityEngine.Rendering;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Draws the mask, depth, normal and labels passes of a view into the capture's render textures with a command buffer
    /// executed at once (<see cref="Graphics.ExecuteCommandBuffer"/>), outside any camera's render loop: no render
    /// pipeline is involved, so URP's depth priming, depth/normal prepasses, MSAA, SSAO and other renderer features,
    /// Forward+ and Deferred cannot change them, and Built-in and URP draw them the same way. The reasoning and the
    /// source lines it rests on are in Documentation~/capture.md, "The data passes".
    /// </summary>
    sealed class DataPassRenderer : IDisposable
    {
        public const int MaskPass = 0;
        public const int DepthPass = 1;
        public const int NormalPass = 2;
        public const int LabelPass = 3;

        static readonly int LabelIdsId = Shader.PropertyToID("_NerfLabelIds");

        readonly struct Draw
        {
            public readonly Renderer Renderer;
            public readonly Material Material;
            public readonly int Submesh;

            public Draw(Renderer renderer, Material material, int submesh)
            {
                Renderer = renderer;
                Material = material;
                Submesh = submesh;
            }
        }

        readonly List<Renderer> _renderers = new List<Renderer>();
        readonly int _cullingMask;
        readonly List<Draw> _draws = new List<Draw>();
        readonly IReadOnlyDictionary<Renderer, RendererLabelIds> _labels;
        DataPassMaterials _materials;
        CommandBuffer _commands;

        /// <param name="renderers">The mesh and skinned-mesh renderers of the capture's copies, enabled or not.</param>
        /// <param name="cullingMask">The capture camera's culling mask: a renderer on a layer it excludes is in no pass.</param>
        /// <param name="labels">
        /// The ids each of <paramref name="renderers"/> is drawn with in the labels pass; a renderer without an entry is
        /// drawn with id 0 (it still hides what is behind it). Null when the capture has no labels pass.
        /// </param>
        public DataPassRenderer(IEnumerable<Renderer> renderers, int cullingMask, IReadOnlyDictionary<Renderer, RendererLabelIds> labels = null)
        {
            try
            {
                _cullingMask = cullingMask;
                _labels = labels;
                _materials = new DataPassMaterials();
                _commands = new CommandBuffer { name = "NeRF Dataset Creator data pass" };
                foreach (var renderer in renderers)
                    if (renderer != null) _renderers.Add(renderer);
                // The data materials of what is drawn now are made (and approximated shaders warned about) before the
                // first view; a renderer switched on later gets its own when it first appears.
                PrepareView();
            }
            catch
            {
                Dispose();
                throw;
            }
        }

        /// <summary>Draw calls per pass (renderer × submesh) of the current view, as of the last <see cref="PrepareView"/>.</summary>
        public int DrawCount => _draws.Count;

        /// <summary>Shaders the data passes draw only approximately (each warned about once in the Console).</summary>
        public IReadOnlyCollection<string> ApproximatedShaders => _materials.ApproximatedShaders;

        /// <summary>
        /// Decides, for the view about to be drawn, what the camera's culling decides for its colour pass: called once
        /// per view, after the content is posed for it. A dynamic capture's <c>ContentClock</c> poses the copies
        /// before each view, and an Animator or a Timeline activation track may switch renderers and objects on and off
        /// (or swap meshes and materials) from one view to the next: a decision taken once per run would leave the data
        /// passes showing what the first view, or the scene before any view, showed.
        /// </summary>
        public void PrepareView()
        {
            _draws.Clear();
            foreach (var renderer in _renderers)
            {
                if (!DrawnByACamera(renderer, _cullingMask)) continue;
                var mesh = MeshOf(renderer);
                if (mesh == null) continue;
                // A camera draws submesh i with material i; submeshes without a material are not drawn, and extra
                // materials draw the last submesh again (same coverage), so min(submeshes, materials) draws suffice.
                var materials = renderer.sharedMaterials;
                var count = Math.Min(mesh.subMeshCount, materials.Length);
                for (var i = 0; i < count; i++) _draws.Add(new Draw(renderer, _materials.For(materials[i]), i));
            }
        }

        /// <summary>
        /// What a camera's culling would keep of the copies, except the frustum (the GPU clips that): enabled and
        /// active, not shadows-only or forced off, on a layer the camera renders. Renderers beyond LOD 0 are
        /// disabled on the copies by <see cref="LodZero"/>, so this leaves them out too.
        /// </summary>
        internal static bool DrawnByACamera(Renderer renderer, int cullingMask) =>
            renderer != null && renderer.enabled && renderer.gameObject.activeInHierarchy && !renderer.forceRenderingOff &&
            renderer.shadowCastingMode != ShadowCastingMode.ShadowsOnly &&
            (cullingMask & (1 << renderer.gameObject.layer)) != 0;

        internal static Mesh MeshOf(Renderer renderer)
        {
            if (renderer is SkinnedMeshRenderer skinned) return skinned.sharedMesh;
            var filter = renderer.GetComponent<MeshFilter>();
            return filter == null ? null : filter.sharedMesh;
        }

        /// <summary>
        /// Renders one data pass of the camera's current view into <paramref name="target"/>, cleared to 0 first, with
        /// the renderers chosen by the last <see cref="PrepareView"/>.
        /// The render target is set before the matrices, so that Unity applies the render-into-texture projection flip
        /// (and the matching winding) exactly as it does for a camera rendering into a texture.
        /// </summary>
        public void Render(Camera camera, RenderTexture target, int pass)
        {
            _commands.Clear();
            _commands.SetRenderTarget(target);
            _commands.ClearRenderTarget(true, true, new Color(0f, 0f, 0f, 0f));
            // The non-GPU projection: Unity converts it for the graphics API and the render target, as URP relies on
            // (URP 14.0.8 ScriptableRenderer.cs:158-163). worldToCameraMatrix is the OpenGL-convention view matrix.
            _commands.SetViewProjectionMatrices(camera.worldToCameraMatrix, camera.projectionMatrix);
            Renderer idsSetFor = null;
            foreach (var draw in _draws)
            {
                if (draw.Renderer == null) continue;
                if (pass == LabelPass && draw.Renderer != idsSetFor)
                {
                    // A global, set in the buffer before this renderer's draws: commands run in order, and the data
                    // materials do not declare _NerfLabelIds, so the global is what the shader reads (Scripting API
                    // Shader.SetGlobalVector; CommandBuffer.SetGlobalVector, UCR 2022.3
                    // Runtime/Export/Graphics/RenderingCommandBuffer.bindings.cs:771, 6000.0 :825).
                    _commands.SetGlobalVector(LabelIdsId, IdsOf(draw.Renderer).Encoded);
                    idsSetFor = draw.Renderer;
                }
                _commands.DrawRenderer(draw.Renderer, draw.Material, draw.Submesh, pass);
            }
            Graphics.ExecuteCommandBuffer(_commands);
        }

        RendererLabelIds IdsOf(Renderer renderer) =>
            _labels != null && _labels.TryGetValue(renderer, out var ids) ? ids : default;

        public void Dispose()
        {
            _draws.Clear();
            _renderers.Clear();
            _commands?.Release();
            _commands = null;
            _materials?.Dispose();
            _materials = null;
        }
    }
}
