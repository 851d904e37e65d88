using System;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The target as the window shows it: Core's measure (centre and bounding radius, from
    /// <see cref="DatasetCapture.MeasureTarget"/>, which the plan uses) and the axis-aligned box of the meshes the
    /// capture renders (for the size shown, "Frame in Scene view" and the preview's box).
    /// </summary>
    sealed class TargetInfo
    {
        TargetInfo(PlanTarget measure, Bounds bounds, bool hasRenderers)
        {
            Measure = measure;
            Bounds = bounds;
            HasRenderers = hasRenderers;
        }

        public PlanTarget Measure { get; }
        public Bounds Bounds { get; }
        public bool HasRenderers { get; }

        public static TargetInfo Of(GameObject target)
        {
            if (target == null) return null;
            PlanTarget measure;
            try
            {
                measure = DatasetCapture.MeasureTarget(target);
            }
            catch (Exception e) when (e is ArgumentException || e is InvalidOperationException)
            {
                // Shown as "no bounds" here; Prepare reports the target's actual problem under the Target field.
                var p = target.transform.position;
                measure = new PlanTarget(new Vector3d(p.x, p.y, p.z), 0);
            }
            var measured = NerfDatasetCreator.Editor.TargetMeshes.WorldBounds(target);
            var bounds = measured ?? new Bounds(target.transform.position, Vector3.zero);
            var any = measured.HasValue;
            return new TargetInfo(measure, bounds, any);
        }
    }
}
