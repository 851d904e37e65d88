using System;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What the Scene-view preview was last built from: the settings that move or shape cameras, and the target's
    /// centre and radius. The window rebuilds the plan only when this key changes, not on every repaint. Names,
    /// folders and output passes are left out because they change no camera.
    /// </summary>
    public sealed class PreviewPlanKey : IEquatable<PreviewPlanKey>
    {
        readonly string _text;

        PreviewPlanKey(string text) => _text = text;

        public static PreviewPlanKey Of(DatasetSettings settings, PlanTarget target)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            var shaping = settings.Clone();
            shaping.Name = "x";
            shaping.OutputFolder = "";
            shaping.Scene = "";
            shaping.Target = "";
            shaping.Overwrite = OverwritePolicy.Never;
            shaping.Loaders = TargetLoaders.All;
            shaping.Background = new BackgroundSettings();
            foreach (var split in DatasetSplits.All)
            {
                var s = shaping.Split(split);
                if (s == null) continue;
                s.Depth = ExtraOutput.None;
                s.Normal = ExtraOutput.None;
                s.Mask = false;
            }
            // Round-trip ("R") formatting: any change of a double changes the key; nothing is lost to rounding.
            var text = DatasetSettingsJson.Write(shaping) + "|" +
                       target.Centre.X.ToString("R", CultureInfo.InvariantCulture) + "," +
                       target.Centre.Y.ToString("R", CultureInfo.InvariantCulture) + "," +
                       target.Centre.Z.ToString("R", CultureInfo.InvariantCulture) + "," +
                       target.BoundingRadius.ToString("R", CultureInfo.InvariantCulture) + SceneCamerasText(settings);
            return new PreviewPlanKey(text);
        }

        /// <summary>The poses and fields of view read from the scene, and the volume boxes: moving a scene camera or a box changes the key.</summary>
        static string SceneCamerasText(DatasetSettings settings)
        {
            var text = new System.Text.StringBuilder();
            foreach (var split in DatasetSplits.All)
            {
                var volume = settings.Split(split)?.Source?.Volume;
                if (volume != null)
                {
                    // Moving the box or any obstacle moves the volume's cameras.
                    text.Append("|volume ").Append(DatasetSplits.Name(split));
                    foreach (var box in new[] { volume.Box }.Concat(volume.Obstacles))
                        text.Append(';').Append(box.Centre.ToString()).Append(box.Rotation.ToString()).Append(box.Size.ToString());
                    // Moving a waypoint moves a path's cameras.
                    foreach (var w in volume.Waypoints ?? Array.Empty<Vector3d>())
                        text.Append(";w").Append(w.X.ToString("R", CultureInfo.InvariantCulture)).Append(',')
                            .Append(w.Y.ToString("R", CultureInfo.InvariantCulture)).Append(',').Append(w.Z.ToString("R", CultureInfo.InvariantCulture));
                }
                var cameras = settings.Split(split)?.Source?.SceneCameras;
                if (cameras == null) continue;
                text.Append('|').Append(DatasetSplits.Name(split));
                foreach (var c in cameras)
                    text.Append(';').Append(c.Pose.Position.X.ToString("R", CultureInfo.InvariantCulture)).Append(',')
                        .Append(c.Pose.Position.Y.ToString("R", CultureInfo.InvariantCulture)).Append(',')
                        .Append(c.Pose.Position.Z.ToString("R", CultureInfo.InvariantCulture)).Append(',')
                        .Append(c.Pose.Rotation.ToString()).Append(',')
                        .Append(c.VerticalFovDegrees.ToString("R", CultureInfo.InvariantCulture));
            }
            return text.ToString();
        }

        public bool Equals(PreviewPlanKey other) => other != null && string.Equals(_text, other._text, StringComparison.Ordinal);

        public override bool Equals(object obj) => Equals(obj as PreviewPlanKey);

        public override int GetHashCode() => StringComparer.Ordinal.GetHashCode(_text);
    }
}
