namespace NerfDatasetCreator
{
    /// <summary>
    /// What only the Unity Editor knows about where a capture came from, recorded in <c>dataset_config.json</c>'s
    /// <c>unity_frame</c> beside the output-to-Unity matrix (issue 34): the target's scene path and GlobalObjectId, its
    /// local-to-world matrix at capture and the project's colour space. Null members are unknown (a plan written
    /// outside Unity knows none of them).
    /// </summary>
    public sealed class UnityFrameFacts
    {
        public UnityFrameFacts(string targetScenePath, string targetGlobalObjectId, double[] targetLocalToWorld, string colorSpace)
        {
            if (targetLocalToWorld != null && targetLocalToWorld.Length != 16)
                throw new System.ArgumentException("A local-to-world matrix has 16 entries (4×4, row-major).", nameof(targetLocalToWorld));
            TargetScenePath = targetScenePath;
            TargetGlobalObjectId = targetGlobalObjectId;
            TargetLocalToWorld = targetLocalToWorld == null ? null : (double[])targetLocalToWorld.Clone();
            ColorSpace = colorSpace;
        }

        /// <summary>The target's hierarchy path in its scene, e.g. "Assets/Scenes/Lego.unity:/Root/Lego".</summary>
        public string TargetScenePath { get; }

        /// <summary><c>GlobalObjectId.GetGlobalObjectIdSlow(target).ToString()</c>, or null where the Editor has none.</summary>
        public string TargetGlobalObjectId { get; }

        /// <summary>The target's <c>Transform.localToWorldMatrix</c> at capture, 16 numbers row-major, in Unity's world.</summary>
        public double[] TargetLocalToWorld { get; }

        /// <summary><c>QualitySettings.activeColorSpace</c> as Unity names it: "Linear" or "Gamma".</summary>
        public string ColorSpace { get; }
    }
}
