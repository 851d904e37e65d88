using System.Collections.Generic;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// How far the target reaches from the output origin, in output units, as a dataset's own
    /// <c>dataset_config.json</c> records it: |s·(P·c_Unity − centre)| + s·b with c_Unity = <c>target.unityCentre</c>,
    /// b = <c>target.boundingRadius</c> and s, centre = <c>scene_normalisation</c> — the same quantity
    /// <see cref="CapturePlan.TargetReach"/> computed when the dataset was captured. Null when the dataset does not say
    /// (nerf_synthetic, a target without renderers, an older config); a record that is there but malformed is a warning,
    /// never a failed conversion.
    /// </summary>
    public static class DatasetTargetReach
    {
        public static double? Read(string datasetDirectory, ICollection<ValidationProblem> warnings = null) =>
            Read(DatasetConfig.Read(datasetDirectory), warnings);

        /// <summary>The reach <paramref name="config"/> records; a config that cannot be read or parsed is a warning.</summary>
        public static double? Read(DatasetConfigFile config, ICollection<ValidationProblem> warnings = null)
        {
            switch (config.State)
            {
                case DatasetConfigState.Missing:
                    return null;
                case DatasetConfigState.Unreadable:
                    warnings?.Add(new ValidationProblem(DatasetLayout.ConfigFileName, config.Path, "cannot be read (" + config.Error + "), so the target's size is unknown.",
                        "Restore the file from the capture, or ignore this if the dataset is not from this plugin."));
                    return null;
                case DatasetConfigState.Read:
                    return config.Config.TargetReach(warnings);
                default:
                    warnings?.Add(new ValidationProblem(DatasetLayout.ConfigFileName, config.Path, "is not valid JSON (" + config.Error + "), so the target's size is unknown.",
                        "Restore the file from the capture, or ignore this if the dataset is not from this plugin."));
                    return null;
            }
        }

        /// <summary>The reach recorded in a parsed <c>dataset_config.json</c>, or null.</summary>
        public static double? FromConfig(JObject config, ICollection<ValidationProblem> warnings = null)
        {
            var sphere = Sphere(config, warnings);
            return sphere.HasValue ? sphere.Value.Centre.Length + sphere.Value.Radius : (double?)null;
        }

        /// <summary>
        /// The target's bounding sphere in the output frame as the parsed <c>dataset_config.json</c> records it: centre
        /// s·(P·c_Unity − centre) (<see cref="SceneNormalisation.ApplyToUnityPoint"/>), radius s·b; null when not recorded.
        /// </summary>
        public static (Vector3d Centre, double Radius)? Sphere(JObject config, ICollection<ValidationProblem> warnings = null)
        {
            var target = config["target"] as JObject;
            var radius = target?["boundingRadius"];
            if (target == null || radius == null || radius.Type == JTokenType.Null) return null;
            var centre = target["unityCentre"] as JArray;
            if (!IsNumber(radius) || !((double)radius >= 0) || centre == null || centre.Count != 3 || !IsNumber(centre[0]) || !IsNumber(centre[1]) || !IsNumber(centre[2]))
            {
                warnings?.Add(new ValidationProblem(DatasetLayout.ConfigFileName + ": target", target.ToString(Formatting.None),
                    "is not a record with a \"unityCentre\" of 3 numbers and a \"boundingRadius\" ≥ 0, so the target's size is unknown.",
                    "Restore the file from the capture."));
                return null;
            }
            SceneNormalisation normalisation;
            try
            {
                normalisation = config[BlenderTransformsWriter.SceneNormalisationKey] == null
                    ? SceneNormalisation.Identity
                    : SceneNormalisation.FromJson(config[BlenderTransformsWriter.SceneNormalisationKey]);
            }
            catch (InvalidParameterException e)
            {
                foreach (var p in e.Problems) warnings?.Add(new ValidationProblem(DatasetLayout.ConfigFileName + ": " + p.Field, p.Value, p.Reason + " The target's size is unknown.", p.Fix));
                return null;
            }
            var unityCentre = new Vector3d((double)centre[0], (double)centre[1], (double)centre[2]);
            return (normalisation.ApplyToUnityPoint(unityCentre), (double)radius * normalisation.Scale);
        }

        static bool IsNumber(JToken t) => t.Type == JTokenType.Float || t.Type == JTokenType.Integer;
    }
}
