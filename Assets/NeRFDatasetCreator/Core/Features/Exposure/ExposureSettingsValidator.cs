using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>The problems of the "exposure" section (<see cref="SettingsValidator"/> adds them), each naming its key.</summary>
    public static class ExposureSettingsValidator
    {
        public static IReadOnlyList<ValidationProblem> Validate(DatasetSettings settings)
        {
            var problems = new List<ValidationProblem>();
            var e = settings?.Exposure;
            if (e == null || e.Mode == ExposureMode.Off) return problems;
            void Add(ValidationProblem p)
            {
                if (p != null) problems.Add(p);
            }
            if (!ExposureModes.IsDefined(e.Mode))
            {
                Add(new ValidationProblem("exposure.mode", ((int)e.Mode).ToString(CultureInfo.InvariantCulture), "is not an exposure mode.", "Use one of " + ExposureModes.NameList() + "."));
                return problems;
            }
            if (!e.Train && !e.Val && !e.Test)
                Add(new ValidationProblem("exposure.splits", "[]", "is empty, so no view would be changed.",
                    "List the splits to modify, e.g. [\"train\"], or set exposure.mode to \"off\"."));
            if (e.Mode == ExposureMode.Random)
            {
                Range(problems, "exposure.evRange", e.EvMin, e.EvMax, -ExposureSettings.MaxEv, ExposureSettings.MaxEv, "stops",
                    "Use e.g. [-1, 1] (a factor of 2 darker to 2 brighter).");
                Range(problems, "exposure.gainRange", e.GainMin, e.GainMax, ExposureSettings.MinGain, ExposureSettings.MaxGain, "",
                    "Use e.g. [0.8, 1.25]; [1, 1] turns white balance off.");
            }
            else
            {
                var values = e.Values;
                if (values == null || values.Count == 0)
                    Add(new ValidationProblem("exposure.values", "[]", "is empty: list mode takes each view's values from this list.",
                        "Give at least one { \"ev\": 0, \"whiteBalance\": [1, 1, 1] }, or use mode \"random\"."));
                else
                {
                    Add(ValidationProblem.OutsideRange("exposure.values", values.Count, 1, ExposureSettings.MaxValues));
                    for (var i = 0; i < values.Count && problems.Count < 20; i++)
                    {
                        var key = "exposure.values[" + i.ToString(CultureInfo.InvariantCulture) + "]";
                        Add(ValidationProblem.OutsideRange(key + ".ev", values[i].Ev, -ExposureSettings.MaxEv, ExposureSettings.MaxEv, "stops"));
                        for (var c = 0; c < 3; c++)
                            Add(ValidationProblem.OutsideRange(key + ".whiteBalance[" + c + "]", values[i].Gain(c), ExposureSettings.MinGain, ExposureSettings.MaxGain));
                    }
                }
            }
            return problems;
        }

        static void Range(List<ValidationProblem> problems, string key, double min, double max, double lowest, double highest, string unit, string fix)
        {
            var a = ValidationProblem.OutsideRange(key + "[0]", min, lowest, highest, unit);
            var b = ValidationProblem.OutsideRange(key + "[1]", max, lowest, highest, unit);
            if (a != null) problems.Add(a);
            if (b != null) problems.Add(b);
            if (a == null && b == null && min > max)
                problems.Add(new ValidationProblem(key, "[" + ValidationProblem.Format(min) + ", " + ValidationProblem.Format(max) + "]",
                    "has its lowest value above its highest.", fix));
        }
    }
}
