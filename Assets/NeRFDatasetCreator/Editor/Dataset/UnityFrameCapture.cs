using System.Collections.Generic;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The Editor's facts about a capture's target for <c>dataset_config.json</c>'s <c>unity_frame</c> (issue 34), read
    /// when the run starts (<see cref="DatasetCapture"/>, window and batch alike). Each call is the public API as the
    /// reference source has it (UnityCsReference at 2022.3.76f1 / 6000.0.78f1):
    /// <list type="bullet">
    /// <item><c>GameObject.scene</c> (Runtime/Export/Scripting/GameObject.bindings.cs:452 / :465) and <c>Scene.path</c>
    /// (Runtime/Export/SceneManager/Scene.cs:43 on both): the scene asset's path, empty for a scene never saved.</item>
    /// <item><c>GlobalObjectId.GetGlobalObjectIdSlow(Object)</c> (Editor/Mono/GlobalObjectId.bindings.cs:27 / :32) and its
    /// <c>ToString()</c> ("GlobalObjectId_V1-…", :50-53 / :55-58); kept only where it identifies something
    /// (<see cref="UnityFrameText.GlobalObjectIdOrNull"/>).</item>
    /// <item><c>Transform.localToWorldMatrix</c> (Runtime/Transform/ScriptBindings/Transform.bindings.cs:111 on both), read
    /// through <c>Matrix4x4[row, column]</c> (Runtime/Export/Math/Matrix4x4.cs:94-99: element row + 4·column of the
    /// column-major storage) into 16 numbers row-major.</item>
    /// <item><c>QualitySettings.activeColorSpace</c> (Runtime/Export/Graphics/GraphicsManagers.bindings.cs:363 / :386),
    /// whose enum names are "Gamma" and "Linear".</item>
    /// </list>
    /// </summary>
    public static class UnityFrameCapture
    {
        /// <summary>The facts for <paramref name="target"/>; a whole-scene capture (no target) records only the colour space.</summary>
        public static UnityFrameFacts Of(GameObject target)
        {
            var colorSpace = QualitySettings.activeColorSpace.ToString();
            if (target == null) return new UnityFrameFacts(null, null, null, colorSpace);
            var names = new List<string>();
            for (var t = target.transform; t != null; t = t.parent) names.Add(t.name);
            names.Reverse();
            var scene = target.scene;
            var path = UnityFrameText.TargetPath(scene.IsValid() ? scene.path : "", names);
            var id = UnityFrameText.GlobalObjectIdOrNull(GlobalObjectId.GetGlobalObjectIdSlow(target).ToString());
            var m = target.transform.localToWorldMatrix;
            return new UnityFrameFacts(path, id, UnityFrameText.RowMajor((row, column) => m[row, column]), colorSpace);
        }
    }
}
