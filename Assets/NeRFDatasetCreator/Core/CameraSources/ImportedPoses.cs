using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The cameras of an existing dataset (<see cref="TransformsPoseReader"/>, <see cref="ColmapModelReader"/>),
    /// placed in the Unity world through the inverse of the output convention and of <see cref="Normalisation"/>.
    /// </summary>
    public sealed class ImportedPoses
    {
        public ImportedPoses(string source, string format, IReadOnlyList<ImportedCamera> cameras, SceneNormalisation normalisation,
            IReadOnlyList<ValidationProblem> warnings)
        {
            Source = source ?? "";
            Format = format ?? "";
            Cameras = cameras ?? throw new ArgumentNullException(nameof(cameras));
            Normalisation = normalisation;
            Warnings = warnings ?? Array.Empty<ValidationProblem>();
        }

        /// <summary>The file or folder read, for messages.</summary>
        public string Source { get; }

        /// <summary><c>transforms</c> (Blender / instant-ngp), <c>nerfstudio</c> or <c>colmap</c>.</summary>
        public string Format { get; }

        public IReadOnlyList<ImportedCamera> Cameras { get; }

        /// <summary>The normalisation the file's matrices are in (its <c>scene_normalisation</c> record or the caller's), or null for none.</summary>
        public SceneNormalisation Normalisation { get; }

        /// <summary>What is read but not reproduced (lens distortion, keys that change nothing here…).</summary>
        public IReadOnlyList<ValidationProblem> Warnings { get; }

        /// <summary>The cameras the file puts in <paramref name="split"/>; all of them for an empty or null split.</summary>
        public IReadOnlyList<ImportedCamera> OfSplit(string split) =>
            string.IsNullOrEmpty(split) ? Cameras : Cameras.Where(c => c.Split == split).ToList();

        /// <summary>The intrinsics every camera of <paramref name="cameras"/> shares, or null when they differ or none is known.</summary>
        public static ImportedIntrinsics SharedIntrinsics(IReadOnlyList<ImportedCamera> cameras)
        {
            if (cameras == null || cameras.Count == 0 || cameras[0].Intrinsics == null) return null;
            var first = cameras[0].Intrinsics;
            return cameras.All(c => first.SameAs(c.Intrinsics)) ? first : null;
        }
    }
}
