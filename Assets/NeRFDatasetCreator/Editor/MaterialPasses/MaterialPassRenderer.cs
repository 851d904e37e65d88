using System;
using System.Collections.Generic;
using UnityEngine;
using UnityEngine.Rendering;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Draws NerfMaterial.shader's passes for the capture's copies with a command buffer executed at once, outside any
    /// camera, exactly as <see cref="DataPassRenderer"/> draws the data passes (same renderers, same culling decision,
    /// same matrices): the Built-in pipeline's material passes, and in both pipelines the coverage pass that says which
    /// samples a supported shader covers.
    /// </summary>
    sealed class MaterialPassRenderer : IDisposable
    {
        public const int CoveragePass = 5;

        readonly List<Renderer> _renderers = new List<Renderer>();
        readonly int _cullingMask;
        readonly List<(Renderer Renderer, Material Material, int Submesh)> _draws = new List<(Renderer, Material, int)>();
        MaterialPassMaterials _materials;
        CommandBuffer _commands;

        public MaterialPassRenderer(IEnumerable<Renderer> renderers, int cullingMask, MaterialPipeline pipeline)
        {
            try
            {
                _cullingMask = cullingMask;
                _materials = new MaterialPassMaterials(pipeline);
                _commands = new CommandBuffer { name = "NeRF Dataset Creator material pass" };
                foreach (var renderer in renderers)
                    if (renderer != null) _renderers.Add(renderer);
            }
            catch
            {
                Dispose();
                throw;
            }
        }

        public MaterialPassMaterials Materials => _materials;

        /// <summary>What a camera would draw now (<see cref="DataPassRenderer.PrepareView"/>'s rule); call once per view.</summary>
        public void PrepareView()
        {
            _draws.Clear();
            foreach (var renderer in _renderers)
            {
                if (!DataPassRenderer.DrawnByACamera(renderer, _cullingMask)) continue;
                var mesh = DataPassRenderer.MeshOf(renderer);
                if (mesh == null) continue;
                var materials = renderer.sharedMaterials;
                var count = Math.Min(mesh.subMeshCount, materials.Length);
                for (var i = 0; i < count; i++) _draws.Add((renderer, _materials.For(materials[i]), i));
            }
        }

        /// <summary>One pass (a <see cref="MaterialPassKind"/> or <see cref="CoveragePass"/>) into <paramref name="target"/>, cleared to 0.</summary>
        public void Render(Camera camera, RenderTexture target, int pass)
        {
            _commands.Clear();
            _commands.SetRenderTarget(target);
            _commands.ClearRenderTarget(true, true, new Color(0f, 0f, 0f, 0f));
            _commands.SetViewProjectionMatrices(camera.worldToCameraMatrix, camera.projectionMatrix);
            foreach (var draw in _draws)
                if (draw.Renderer != null) _commands.DrawRenderer(draw.Renderer, draw.Material, draw.Submesh, pass);
            Graphics.ExecuteCommandBuffer(_commands);
        }

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
