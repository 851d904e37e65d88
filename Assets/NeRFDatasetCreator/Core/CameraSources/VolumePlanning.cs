using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>What the Unity editor read for a volume source: the capture box and the obstacle boxes of the scene.</summary>
    public sealed class VolumeScene
    {
        public VolumeScene(OrientedBox box, IReadOnlyList<OrientedBox> obstacles, IReadOnlyList<Vector3d> waypoints = null)
        {
            Box = box ?? throw new ArgumentNullException(nameof(box));
            Obstacles = obstacles ?? Array.Empty<OrientedBox>();
            Waypoints = waypoints;
        }

        public OrientedBox Box { get; }
        public IReadOnlyList<OrientedBox> Obstacles { get; }

        /// <summary><see cref="VolumeLook.Path"/>: the waypoint object's children's world positions in order; null otherwise.</summary>
        public IReadOnlyList<Vector3d> Waypoints { get; }
    }

    /// <summary>
    /// A volume source as <see cref="CapturePlan"/> sees it: <see cref="VolumeSampling"/> in the box the editor read,
    /// seeded by the dataset's seed and the split's name, the kept poses becoming the split's cameras like scene
    /// cameras (rendered with the Camera step's lens, written through the dataset's normalisation). The rejected
    /// positions are reported as a warning, and too few kept positions stop the plan.
    /// </summary>
    public static class VolumePlanning
    {
        /// <summary>The <see cref="ImportedPoses.Format"/> of volume cameras.</summary>
        public const string Format = "volume";

        static readonly string[] LookNames = { "ring", "sphere", "forward", "path" };

        public static string LookName(VolumeLook look) => LookNames[(int)look];

        public static bool TryParseLook(string name, out VolumeLook look)
        {
            var i = Array.FindIndex(LookNames, n => string.Equals(n, name, StringComparison.OrdinalIgnoreCase));
            look = i < 0 ? VolumeLook.Ring : (VolumeLook)i;
            return i >= 0;
        }

        /// <summary>The seed of a split's volume: independent of its formation's stream.</summary>
        public static long Seed(long datasetSeed, string splitName) => SeededRandom.Derive(datasetSeed, "volume/" + splitName);

        public static IEnumerable<ValidationProblem> Validate(CameraSourceSettings s, string field)
        {
            if (string.IsNullOrWhiteSpace(s.ObjectPath))
                yield return new ValidationProblem(field + ".box", "\"\"", "is empty; a volume source needs the object whose box the cameras fill.",
                    "Give the hierarchy path of an object whose Transform (position, rotation, scale) is the box, e.g. \"CaptureVolume\".");
            if (double.IsNaN(s.Density) || double.IsInfinity(s.Density) || s.Density < 0)
                yield return new ValidationProblem(field + ".density", ValidationProblem.Format(s.Density), "must be 0 (use the split's count) or a positive number of cameras per cubic unit.",
                    "Use 0 or a positive number.");
            if (s.Look == VolumeLook.Path && string.IsNullOrWhiteSpace(s.PathObject))
                yield return new ValidationProblem(field + ".waypoints", "\"\"", "is empty; look \"path\" needs the object whose children are the waypoints.",
                    "Give the hierarchy path of an object whose children, in hierarchy order, mark the path (e.g. \"Flythrough\").");
            if (s.Look == VolumeLook.Path && s.Density > 0)
                yield return new ValidationProblem(field + ".density", ValidationProblem.Format(s.Density), "counts cameras per cubic unit of the box, which a path does not fill.",
                    "Use 0 and the split's count for cameras along a path.");
            if (!(s.JitterDegrees >= 0 && s.JitterDegrees <= 180))
                yield return ValidationProblem.OutsideRange(field + ".jitterDegrees", s.JitterDegrees, 0, 180, "°");
            if (double.IsNaN(s.Clearance) || double.IsInfinity(s.Clearance) || s.Clearance < 0)
                yield return new ValidationProblem(field + ".clearance", ValidationProblem.Format(s.Clearance), "must be a distance of 0 or more.",
                    "Use at least the camera's near clip plane, so that no wall is cut open in front of a camera.");
        }

        /// <summary>How many cameras the split wants: its count, or the density times the box's volume (rounded up).</summary>
        public static double WantedCount(CameraSourceSettings s, int splitCount, OrientedBox box) =>
            s.Density > 0 ? Math.Ceiling(s.Density * box.Volume) : splitCount;

        /// <summary>The split's cameras, or null with a problem.</summary>
        public static ImportedSplit Resolve(CameraSourceSettings source, string field, int splitCount, long seed, string splitName, List<ValidationProblem> problems)
        {
            if (source.SceneProblem != null)
            {
                problems.Add(source.SceneProblem);
                return null;
            }
            var scene = source.Volume;
            if (scene == null)
            {
                problems.Add(new ValidationProblem(field + ".kind", "\"volume\"",
                    "samples cameras in a box of a Unity scene, which only the Unity editor can read (nerf-dataset has no scene).",
                    "Plan and capture this config in Unity (window or batch mode), or give the split a formation or imported cameras."));
                return null;
            }
            var box = scene.Box;
            if (!box.IsFinite || !(box.Volume > 0))
            {
                problems.Add(new ValidationProblem(field + ".box", source.ObjectPath, "has a box of size " + box.Size + ", which holds no positions.",
                    "Scale the box object to a size above 0 on every axis (its Transform's scale is the box's size)."));
                return null;
            }
            var wanted = WantedCount(source, splitCount, box);
            if (wanted < 1 || wanted > DatasetSettings.MaxViews)
            {
                problems.Add(source.Density > 0
                    ? new ValidationProblem(field + ".density", ValidationProblem.Format(source.Density),
                        "asks for " + ValidationProblem.Format(wanted) + " cameras in a box of " + ValidationProblem.Format(box.Volume) + " cubic units; a split holds 1 to " + DatasetSettings.MaxViews + ".",
                        "Lower or raise the density, or use 0 and the split's count.")
                    : ValidationProblem.OutsideRange(field.Substring(0, field.LastIndexOf('.')) + ".count", wanted, 1, DatasetSettings.MaxViews));
                return null;
            }
            var count = (int)wanted;
            if (source.Look == VolumeLook.Path) return AlongPath(source, scene, field, count, seed, splitName, problems);
            var sample = VolumeSampling.Sample(box, scene.Obstacles, source.Clearance, count, source.Look, source.JitterDegrees, seed);
            if (sample.Poses.Count < count)
            {
                problems.Add(new ValidationProblem(field + ".box", source.ObjectPath,
                    "has room for only " + sample.Poses.Count + " of the " + count + " cameras: " + sample.Rejected + " of " + sample.Drawn +
                    " positions drawn were inside an obstacle or nearer than the clearance (" + ValidationProblem.Format(source.Clearance) + ") to one (" + Worst(sample) + ").",
                    "Move or enlarge the box into open space, lower the clearance, or ask for fewer cameras."));
                return null;
            }
            var warnings = new List<ValidationProblem>();
            if (sample.Rejected > 0)
                warnings.Add(new ValidationProblem(field + ".box", source.ObjectPath,
                    "rejected " + sample.Rejected + " of " + sample.Drawn + " positions drawn (inside an obstacle or nearer than " +
                    ValidationProblem.Format(source.Clearance) + " to one: " + Worst(sample) + "); " + count + " cameras kept.",
                    "Nothing to do if the box overlaps walls or props on purpose; otherwise check the obstacles listed."));
            var cameras = sample.Poses.Select((pose, i) => new ImportedCamera(splitName + "_" + i.ToString(CultureInfo.InvariantCulture), null,
                BlenderConvention.CameraToWorld(pose), pose, null)).ToList();
            // Normalisation null: the cameras are in the raw output world, so PosePlacement.ToOutput applies the
            // dataset's normalisation to them as to a formation's poses.
            return new ImportedSplit(new ImportedPoses(source.ObjectPath, Format, cameras, null, warnings), cameras, field);
        }

        /// <summary>The box of every split with views that samples an inside-out volume, in the Unity world, train first.</summary>
        public static IReadOnlyList<KeyValuePair<DatasetSplit, OrientedBox>> Boxes(CapturePlan plan)
        {
            var boxes = new List<KeyValuePair<DatasetSplit, OrientedBox>>();
            foreach (var split in DatasetSplits.All)
            {
                var source = plan.Settings.Split(split)?.Source;
                if (source == null || !source.IsVolume || source.Volume == null || !plan.ViewsOf(split).Any()) continue;
                boxes.Add(new KeyValuePair<DatasetSplit, OrientedBox>(split, source.Volume.Box));
            }
            return boxes;
        }

        /// <summary>
        /// <see cref="VolumeLook.Path"/>: <paramref name="count"/> cameras along the waypoints' spline. The path is the
        /// user's, so a camera inside an obstacle is not moved or dropped but counted in a warning that names it.
        /// </summary>
        static ImportedSplit AlongPath(CameraSourceSettings source, VolumeScene scene, string field, int count, long seed, string splitName, List<ValidationProblem> problems)
        {
            CatmullRomPath path;
            try { path = new CatmullRomPath(scene.Waypoints ?? Array.Empty<Vector3d>()); }
            catch (ArgumentException)
            {
                problems.Add(new ValidationProblem(field + ".waypoints", source.PathObject,
                    "has " + (scene.Waypoints?.Count ?? 0) + " children at distinct places; a path needs at least two waypoints.",
                    "Add child objects under it, in the order the cameras should pass them."));
                return null;
            }
            var poses = PathSampling.Sample(path, count, source.JitterDegrees, seed);
            var warnings = new List<ValidationProblem>();
            var inside = new Dictionary<string, int>();
            foreach (var pose in poses)
                foreach (var o in scene.Obstacles)
                    if (o.Contains(pose.Position, source.Clearance))
                    {
                        inside.TryGetValue(o.Name, out var n);
                        inside[o.Name] = n + 1;
                        break;
                    }
            if (inside.Count > 0)
                warnings.Add(new ValidationProblem(field + ".waypoints", source.PathObject,
                    "puts " + inside.Values.Sum() + " of " + count + " cameras inside an obstacle or nearer than " + ValidationProblem.Format(source.Clearance) +
                    " to one (" + string.Join(", ", inside.OrderByDescending(p => p.Value).Take(3).Select(p => (p.Key.Length > 0 ? p.Key : "unnamed") + " " + p.Value)) + ").",
                    "Move the waypoints into open space; the path's cameras are kept where it puts them."));
            var cameras = poses.Select((pose, i) => new ImportedCamera(splitName + "_" + i.ToString(CultureInfo.InvariantCulture), null,
                BlenderConvention.CameraToWorld(pose), pose, null)).ToList();
            return new ImportedSplit(new ImportedPoses(source.PathObject, Format, cameras, null, warnings), cameras, field);
        }

        /// <summary>
        /// For NeRF's Blender loaders, when a split with views is an inside-out volume: they sample every ray only
        /// between near 2 and far 6 (<see cref="LoaderRangeCheck"/>), which an environment seen from inside does not
        /// fit; null otherwise.
        /// </summary>
        public static ValidationProblem InsideOutWarning(DatasetSettings settings)
        {
            foreach (var split in DatasetSplits.All)
            {
                var s = settings.Split(split);
                if (s?.Source == null || !s.Source.IsVolume || s.Count == 0) continue;
                return new ValidationProblem("splits." + DatasetSplits.Name(split) + ".source", "\"volume\"",
                    "places cameras inside the scene looking out. NeRF's Blender loaders (bmild/nerf, nerf-pytorch) sample every ray only between 2 and 6 units from the camera, so nearer walls and farther scenery are lost: they cannot train this dataset.",
                    "Train with the other exports: nerfstudio (nerfacto's scene contraction), instant-ngp (aabb_scale up to 128) or 3DGS (COLMAP); or leave \"nerf\" out of loaders.");
            }
            return null;
        }

        /// <summary>"Walls/North 120, Props/Crate 3" — the obstacles that rejected most, for messages.</summary>
        static string Worst(VolumeSample sample) =>
            string.Join(", ", sample.RejectedBy.OrderByDescending(p => p.Value).ThenBy(p => p.Key, StringComparer.Ordinal).Take(3)
                .Select(p => (p.Key.Length > 0 ? p.Key : "unnamed") + " " + p.Value)) + (sample.RejectedBy.Count > 3 ? ", …" : "");
    }
}
