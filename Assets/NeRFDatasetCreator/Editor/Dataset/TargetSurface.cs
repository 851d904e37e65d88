using System.Collections.Generic;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The target's mesh surfaces in Unity's world, for <c>points3d.ply</c>: every enabled MeshRenderer with a
    /// MeshFilter mesh, and every enabled SkinnedMeshRenderer in its current pose (BakeMesh), on the target and its
    /// active children — the renderers the capture draws. Only copies arrays out of Unity; the transform (points by
    /// the local-to-world matrix, normals by its normal matrix) is <see cref="WorldSurface"/>'s, sampling is Core's.
    /// Colours, as sRGB display values in [0, 1] (what a PLY's 8-bit colours hold): the mesh's vertex colours when it
    /// has them, else per submesh the material's <c>_BaseColor</c> (URP) or <c>_Color</c> (Built-in) as the
    /// inspector shows it (Material.GetColor returns non-HDR colours unconverted), else grey. Textures are not sampled.
    /// </summary>
    public static class TargetSurface
    {
        static readonly Vector3d Grey = new Vector3d(0.5, 0.5, 0.5);

        /// <summary>
        /// The meshes of every active root object of the loaded scenes — what a whole-scene capture copies and renders
        /// (CaptureStage's sources: DontSave and inactive roots left out) — for an environment's points3d.ply.
        /// </summary>
        public static List<SurfaceMesh> CollectScene(List<ValidationProblem> warnings)
        {
            var meshes = new List<SurfaceMesh>();
            for (var i = 0; i < UnityEngine.SceneManagement.SceneManager.sceneCount; i++)
            {
                var scene = UnityEngine.SceneManagement.SceneManager.GetSceneAt(i);
                if (!scene.isLoaded) continue;
                foreach (var root in scene.GetRootGameObjects())
                    if ((root.hideFlags & HideFlags.DontSave) == 0 && root.activeInHierarchy) meshes.AddRange(Collect(root, warnings));
            }
            return meshes;
        }

        /// <summary>The meshes; renderers that cannot be read add a warning instead.</summary>
        public static List<SurfaceMesh> Collect(GameObject target, List<ValidationProblem> warnings)
        {
            var meshes = new List<SurfaceMesh>();
            if (target == null) return meshes;
            foreach (var pair in TargetMeshes.Of(target))
            {
                var renderer = pair.Key;
                if (renderer is SkinnedMeshRenderer skinned)
                {
                    var baked = new Mesh();
                    try
                    {
                        // useScale true "compensates for the SkinnedMeshRenderer's Transform scale. If true, the baked
                        // Mesh is the same size as the original. If false, the baked Mesh matches the scaling of the
                        // Transform" (Scripting API SkinnedMeshRenderer.BakeMesh, 2023.2 and 6000.x wording; 2022.3
                        // says the same less plainly), and position and rotation are always compensated. So the baked
                        // vertices are in the renderer's local space, scale not applied, and the full localToWorldMatrix
                        // (scale included, once) takes them to the world like a MeshFilter's. With useScale false the
                        // matrix would have to drop the scale. Checked by SkinnedTargetSurfaceTests (0.01 parent).
                        skinned.BakeMesh(baked, true);
                        Add(meshes, warnings, renderer, baked, skinned.sharedMesh.name);
                    }
                    finally
                    {
                        Object.DestroyImmediate(baked);
                    }
                }
                else Add(meshes, warnings, renderer, pair.Value, pair.Value.name);
            }
            return meshes;
        }

        static void Add(List<SurfaceMesh> meshes, List<ValidationProblem> warnings, Renderer renderer, Mesh mesh, string meshName)
        {
            var field = "pointCloudPoints";
            var where = renderer.name + " (mesh '" + meshName + "')";
            // Unity allows reading meshes without Read/Write in the editor outside Play mode (the capture refuses Play mode).
            if (!mesh.isReadable && EditorApplication.isPlayingOrWillChangePlaymode)
            {
                warnings.Add(new ValidationProblem(field, where, "is not readable in Play mode, so the point cloud leaves it out.",
                    "Stop Play mode, or enable Read/Write in the model's import settings."));
                return;
            }
            var vertices = mesh.vertices;
            if (vertices.Length == 0)
            {
                if (mesh.vertexCount > 0)
                    warnings.Add(new ValidationProblem(field, where, "refused to give its vertices (Read/Write is off), so the point cloud leaves it out.",
                        "Enable Read/Write in the model's import settings."));
                return;
            }

            var normals = mesh.normals;
            var colours = mesh.colors;
            var materials = renderer.sharedMaterials;
            var triangles = new List<int>();
            var triangleColours = colours.Length == vertices.Length ? null : new List<Vector3d>();
            // Submesh i is drawn with material i; submeshes beyond the materials are not drawn, so not sampled.
            var submeshes = Mathf.Min(mesh.subMeshCount, materials.Length);
            for (var s = 0; s < submeshes; s++)
            {
                var before = triangles.Count;
                var topology = mesh.GetTopology(s);
                if (topology == MeshTopology.Triangles) triangles.AddRange(mesh.GetTriangles(s));
                else if (topology == MeshTopology.Quads)
                {
                    var quads = mesh.GetIndices(s);
                    for (var q = 0; q + 3 < quads.Length; q += 4)
                        triangles.AddRange(new[] { quads[q], quads[q + 1], quads[q + 2], quads[q], quads[q + 2], quads[q + 3] });
                }
                else continue; // lines and points have no area
                if (triangleColours == null) continue;
                var colour = MaterialColour(materials[s]);
                for (var t = before / 3; t < triangles.Count / 3; t++) triangleColours.Add(colour);
            }
            if (triangles.Count == 0) return;

            meshes.Add(WorldSurface.FromLocal(ToCore(vertices), triangles, ToCore(renderer.transform.localToWorldMatrix),
                normals.Length == vertices.Length ? ToCore(normals) : null,
                triangleColours == null ? ToCore(colours) : null,
                triangleColours, where));
        }

        static Vector3d MaterialColour(Material material)
        {
            if (material == null) return Grey;
            Color c;
            if (material.HasProperty("_BaseColor")) c = material.GetColor("_BaseColor");
            else if (material.HasProperty("_Color")) c = material.GetColor("_Color");
            else return Grey;
            return new Vector3d(c.r, c.g, c.b);
        }

        static Vector3d[] ToCore(Vector3[] values)
        {
            var result = new Vector3d[values.Length];
            for (var i = 0; i < values.Length; i++) result[i] = new Vector3d(values[i].x, values[i].y, values[i].z);
            return result;
        }

        static Vector3d[] ToCore(Color[] values)
        {
            var result = new Vector3d[values.Length];
            for (var i = 0; i < values.Length; i++) result[i] = new Vector3d(values[i].r, values[i].g, values[i].b);
            return result;
        }

        static Matrix4x4d ToCore(Matrix4x4 m)
        {
            var rows = new double[16];
            for (var r = 0; r < 4; r++)
                for (var c = 0; c < 4; c++) rows[r * 4 + c] = m[r, c];
            return Matrix4x4d.FromRowMajor(rows);
        }
    }
}
