using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>The loaders a dataset is meant for; validation checks each chosen loader's split needs.</summary>
    [Flags]
    public enum TargetLoaders
    {
        None = 0,
        /// <summary>bmild/nerf and nerf-pytorch: open all three transforms files and stack their images.</summary>
        Nerf = 1,
        /// <summary>instant-ngp, pointed at transforms_train.json.</summary>
        InstantNgp = 2,
        /// <summary>nerfstudio <c>blender-data</c>: train, and val as its default evaluation split.</summary>
        Nerfstudio = 4,
        /// <summary>3D Gaussian Splatting: train (test is optional, val is ignored).</summary>
        GaussianSplatting = 8,
        All = Nerf | InstantNgp | Nerfstudio | GaussianSplatting,
    }

    public static class TargetLoaderNames
    {
        static readonly KeyValuePair<TargetLoaders, string>[] Names =
        {
            new KeyValuePair<TargetLoaders, string>(TargetLoaders.Nerf, "nerf"),
            new KeyValuePair<TargetLoaders, string>(TargetLoaders.InstantNgp, "instant-ngp"),
            new KeyValuePair<TargetLoaders, string>(TargetLoaders.Nerfstudio, "nerfstudio"),
            new KeyValuePair<TargetLoaders, string>(TargetLoaders.GaussianSplatting, "3dgs"),
        };

        public static IEnumerable<string> NamesOf(TargetLoaders loaders)
        {
            foreach (var pair in Names)
                if ((loaders & pair.Key) != 0) yield return pair.Value;
        }

        public static bool TryParse(string name, out TargetLoaders loader)
        {
            foreach (var pair in Names)
                if (string.Equals(pair.Value, name, StringComparison.OrdinalIgnoreCase))
                {
                    loader = pair.Key;
                    return true;
                }
            loader = TargetLoaders.None;
            return false;
        }

        public static string NameList() => string.Join(", ", new List<KeyValuePair<TargetLoaders, string>>(Names).ConvertAll(p => p.Value));

        /// <summary>The splits <paramref name="loader"/> cannot work without (see Documentation~/settings.md).</summary>
        public static IEnumerable<DatasetSplit> RequiredSplits(TargetLoaders loader)
        {
            switch (loader)
            {
                case TargetLoaders.Nerf: return new[] { DatasetSplit.Train, DatasetSplit.Val, DatasetSplit.Test };
                case TargetLoaders.InstantNgp: return new[] { DatasetSplit.Train };
                case TargetLoaders.Nerfstudio: return new[] { DatasetSplit.Train, DatasetSplit.Val };
                case TargetLoaders.GaussianSplatting: return new[] { DatasetSplit.Train };
                default: return Array.Empty<DatasetSplit>();
            }
        }

        public static string DisplayName(TargetLoaders loader)
        {
            foreach (var pair in Names)
                if (pair.Key == loader) return pair.Value;
            return loader.ToString();
        }
    }
}
