using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The exposure and white balance of every view, a pure function of the settings, the seed, the split and the view's
    /// index: view i gets the same values whichever shard renders it, and the transforms writer and the image writer
    /// compute them independently and agree. Random draws come from a SplitMix64 stream seeded by a hash of
    /// (seed, "exposure", split, index) — no sequence is shared between views, so no view's values depend on another's.
    /// </summary>
    public sealed class ExposurePlan
    {
        readonly ExposureSettings _settings;
        readonly long[] _splitSeeds = new long[3];

        ExposurePlan(ExposureSettings settings, long seed)
        {
            _settings = settings;
            foreach (var split in DatasetSplits.All) _splitSeeds[(int)split] = SeededRandom.Derive(seed, "exposure/" + DatasetSplits.Name(split));
        }

        /// <summary>The plan of <paramref name="settings"/>, or null when exposure is off (nothing changes).</summary>
        public static ExposurePlan Of(DatasetSettings settings) =>
            settings?.Exposure == null || !settings.Exposure.Enabled ? null : new ExposurePlan(settings.Exposure, settings.Seed);

        public ExposureSettings Settings => _settings;

        public bool Applies(DatasetSplit split) => _settings.Applies(split);

        /// <summary>True when the views of <paramref name="split"/> also get their unmodified image.</summary>
        public bool WritesClean(DatasetSplit split) => _settings.WriteClean && _settings.Applies(split);

        /// <summary>View <paramref name="index"/>'s values (identity in a split that is not modified).</summary>
        public ViewExposure For(DatasetSplit split, int index)
        {
            if (!Applies(split)) return ViewExposure.Identity;
            if (_settings.Mode == ExposureMode.List)
            {
                var values = _settings.Values;
                return values == null || values.Count == 0 ? ViewExposure.Identity : values[index % values.Count];
            }
            // The view's own stream: SplitMix64 from a hash of the split's seed and the index (one mixing step).
            var hash = new SeededRandom(unchecked(_splitSeeds[(int)split] ^ ((long)index * -7046029254386353131L))).NextUInt64();
            var random = new SeededRandom(unchecked((long)hash));
            var ev = Lerp(_settings.EvMin, _settings.EvMax, random.NextDouble());
            var r = LogUniform(random.NextDouble());
            var b = LogUniform(random.NextDouble());
            return new ViewExposure(ev, r, 1, b);
        }

        static double Lerp(double min, double max, double u) => min == max ? min : min + (max - min) * u;

        double LogUniform(double u)
        {
            double min = _settings.GainMin, max = _settings.GainMax;
            return min == max ? min : Math.Exp(Lerp(Math.Log(min), Math.Log(max), u));
        }
    }
}
