using System.Collections.Generic;
using System.Linq;
using GaussianSplatting.Runtime;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor.GaussianSplatting
{
    /// <summary>
    /// Registers <see cref="ArasPSplatViewer"/> when the editor loads. This assembly exists only where aras-p's package
    /// (org.nesnausk.gaussian-splatting 1.x) is installed: its asmdef's <c>versionDefines</c> sets NERF_GAUSSIAN_SPLATTING
    /// for that package and <c>defineConstraints</c> requires it (Unity Manual, "Assembly definition properties": version
    /// defines, define constraints), so without the package nothing here is compiled and nothing references it.
    /// </summary>
    [InitializeOnLoad]
    static class ArasPSplatViewerRegistration
    {
        static ArasPSplatViewerRegistration() => SplatViewers.Register(new ArasPSplatViewer());
    }

    /// <summary>
    /// Places a <c>GaussianSplatRenderer</c> with the PLY's <c>GaussianSplatAsset</c>, through the package's public API only
    /// (github.com/aras-p/UnityGaussianSplatting v1.1.1, 9310dce438da726244ace17eaf6f768826435fa4, under <c>package/</c>):
    /// <list type="bullet">
    /// <item>The renderer's public fields <c>m_Asset</c> and its shader / compute shader fields (Runtime/GaussianSplatRenderer.cs:225,
    /// 246-251). Its rendering uses the GameObject's transform — centres through <c>localToWorldMatrix</c>, view data through
    /// <c>worldToCameraMatrix · localToWorldMatrix</c> and <c>worldToLocalMatrix</c> (CalcViewData, :584-599) — so the splat is
    /// placed by its Transform and never rewritten.</item>
    /// <item>The asset creator (Editor/GaussianSplatAssetCreator.cs) has no public API that makes an asset: its window opens
    /// from <c>Init()</c>/the menu (:60-67) and <c>CreateAsset()</c> is private (:247). An existing asset made from the PLY is
    /// found by the name the creator gives it (:293, <see cref="ArasPSplatConventions.AssetName"/>); otherwise the user is
    /// given the exact steps and the creator's window is opened.</item>
    /// </list>
    /// </summary>
    sealed class ArasPSplatViewer : ISplatViewer
    {
        const string CreatorMenu = "Tools/Gaussian Splats/Create GaussianSplatAsset"; // GaussianSplatAssetCreator.cs:60

        public string Name => "aras-p's Gaussian Splatting (" + SplatViewers.ArasPPackage + ")";

        public SplatViewerResult Place(string plyPath, Transform parent, SplatUnderParent local, string objectName, GameObject existing)
        {
            var lines = new List<string>();
            var asset = FindAsset(plyPath, lines);
            GameObject go;
            GaussianSplatRenderer renderer;
            if (existing != null && existing.TryGetComponent(out renderer))
                go = existing; // Place again: the same object, moved and given the asset.
            else
            {
                // Undo.RegisterCreatedObjectUndo / AddComponent<T> / SetTransformParent / RecordObject (UnityCsReference
                // Editor/Mono/Undo/Undo.bindings.cs:132, 168, 116, 192 on 2022.3.76f1 and 6000.0.78f1): one undoable placement.
                go = new GameObject(objectName);
                Undo.RegisterCreatedObjectUndo(go, "Place trained splat");
                renderer = Undo.AddComponent<GaussianSplatRenderer>(go);
            }
            Undo.SetTransformParent(go.transform, parent, "Place trained splat");
            Undo.RecordObject(go.transform, "Place trained splat");
            go.transform.localPosition = local.Position.ToVector3();
            go.transform.localRotation = local.Rotation.ToQuaternion();
            go.transform.localScale = local.Scale.ToVector3();
            Undo.RecordObject(renderer, "Place trained splat");
            FillResources(renderer);
            if (asset != null) renderer.m_Asset = asset;
            lines.Insert(0, "Placed \"" + go.name + "\"" + (parent != null ? " under \"" + parent.name + "\"" : " at the scene root") + ".");
            if (asset != null)
                lines.Add(asset.cameras != null && asset.cameras.Length > 0
                    ? "Its camera slider holds " + asset.cameras.Length + " cameras (the package gives each a 25° field of view; View from camera i uses the dataset's)."
                    : "Its asset has no cameras: make it again with Import Cameras on after place-splat wrote cameras.json.");
            return new SplatViewerResult(go, lines);
        }

        /// <summary>The asset the creator made from <paramref name="plyPath"/>, found by its name; null with the steps to make it.</summary>
        static GaussianSplatAsset FindAsset(string plyPath, List<string> lines)
        {
            var name = ArasPSplatConventions.AssetName(plyPath);
            // AssetDatabase.FindAssets (Editor/Mono/AssetDatabase/AssetDatabaseSearching.cs:16 / :17) matches names by
            // substring, so the names are compared exactly here.
            var paths = AssetDatabase.FindAssets(name + " t:" + nameof(GaussianSplatAsset))
                .Select(AssetDatabase.GUIDToAssetPath)
                .Where(p => System.IO.Path.GetFileNameWithoutExtension(p) == name)
                .OrderBy(p => p, System.StringComparer.Ordinal).ToList();
            if (paths.Count > 0)
            {
                if (paths.Count > 1) lines.Add(paths.Count + " assets are named \"" + name + "\"; using " + paths[0] + ".");
                return AssetDatabase.LoadAssetAtPath<GaussianSplatAsset>(paths[0]);
            }
            var cameras = ArasPSplatConventions.CamerasJsonFor(plyPath);
            lines.Add("No GaussianSplatAsset named \"" + name + "\" exists, and the package's creator has no public API to make one. Make it:");
            lines.Add("  1. Tools ▸ Gaussian Splats ▸ Create GaussianSplatAsset (opened for you).");
            lines.Add("  2. Input PLY/SPZ File: " + plyPath);
            lines.Add("  3. Import Cameras: on — " + (cameras != null ? "it reads " + cameras : "no cameras.json is found above the PLY, so the slider will have no cameras") + ".");
            lines.Add("  4. Output Folder inside Assets/, then Create Asset.");
            lines.Add("  5. Press Place again: this object is kept and given the asset.");
            // EditorApplication.ExecuteMenuItem (Editor/Mono/EditorApplication.bindings.cs:167 / :161): the creator's own menu item.
            EditorApplication.delayCall += () => EditorApplication.ExecuteMenuItem(CreatorMenu);
            return null;
        }

        /// <summary>
        /// The shaders the renderer needs, from its script's default references where they are empty (GaussianSplatRenderer.cs.meta
        /// lists them; whether Undo.AddComponent applies them is native): MonoScript.FromMonoBehaviour (Editor/Mono/MonoScript.bindings.cs:26)
        /// and MonoImporter.GetDefaultReference(string) (Modules/AssetPipelineEditor/Public/MonoImporter.bindings.cs:36 / :32).
        /// </summary>
        static void FillResources(GaussianSplatRenderer renderer)
        {
            var script = MonoScript.FromMonoBehaviour(renderer);
            if (!(AssetImporter.GetAtPath(AssetDatabase.GetAssetPath(script)) is MonoImporter importer)) return;
            if (renderer.m_ShaderSplats == null) renderer.m_ShaderSplats = importer.GetDefaultReference("m_ShaderSplats") as Shader;
            if (renderer.m_ShaderComposite == null) renderer.m_ShaderComposite = importer.GetDefaultReference("m_ShaderComposite") as Shader;
            if (renderer.m_ShaderDebugPoints == null) renderer.m_ShaderDebugPoints = importer.GetDefaultReference("m_ShaderDebugPoints") as Shader;
            if (renderer.m_ShaderDebugBoxes == null) renderer.m_ShaderDebugBoxes = importer.GetDefaultReference("m_ShaderDebugBoxes") as Shader;
            if (renderer.m_CSSplatUtilities == null) renderer.m_CSSplatUtilities = importer.GetDefaultReference("m_CSSplatUtilities") as ComputeShader;
        }
    }
}
