using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The ordered list of views a run captures — train, then val, then test, each by index — built from settings
    /// alone, so the same settings and seed give the same plan, byte for byte (<see cref="CapturePlanJson"/>).
    /// Cameras are placed by <see cref="CameraRig.Place"/> around the target's centre; random formations draw from
    /// <c>SeededRandom.Derive(seed, splitName)</c>. Output poses go through the settings' <see cref="SceneNormalisation"/>
    /// (by default recentred on the target at unit scale: the target's centre is the output origin and one output
    /// unit is one Unity unit); <see cref="Warnings"/> says where the result breaks a chosen loader's fixed range.
    /// </summary>
    public sealed class CapturePlan
    {
        CapturePlan(DatasetSettings settings, PlanTarget target, double distance, CameraIntrinsics intrinsics,
            SceneNormalisation normalisation, IReadOnlyList<ValidationProblem> warnings, PlannedViewList views, TimeRange time)
        {
            Time = time;
            Settings = settings;
            Target = target;
            Distance = distance;
            Intrinsics = intrinsics;
            Normalisation = normalisation;
            Warnings = warnings;
            _views = views;
        }

        readonly PlannedViewList _views;

        /// <summary>A private copy of the settings the plan was built from.</summary>
        public DatasetSettings Settings { get; }

        public PlanTarget Target { get; }

        /// <summary>The camera distance actually used (the automatic one when settings ask for it).</summary>
        public double Distance { get; }

        public CameraIntrinsics Intrinsics { get; }

        /// <summary>The similarity from the (Blender-relabelled) Unity world to the output world; its scale also scales depth.</summary>
        public SceneNormalisation Normalisation { get; }

        /// <summary>
        /// Where the output breaks a fixed range of a loader in <see cref="DatasetSettings.Loaders"/> (NeRF's near 2 /
        /// far 6, 3DGS's ±1.3 initial cloud, nerfstudio's ±1.5 box, instant-ngp's largest aabb_scale): the dataset is
        /// still valid, so these never stop a run. Always the whole dataset's, also in a shard's plan.
        /// </summary>
        public IReadOnlyList<ValidationProblem> Warnings { get; }

        /// <summary>The target's reach from the output origin in output units: |normalised centre| + s·b (0 with unknown bounds).</summary>
        public double TargetReach => PlanWarnings.TargetReach(Target, Normalisation);

        /// <summary>instant-ngp's <c>aabb_scale</c> for a cube that holds the target (<see cref="AabbScale"/>).</summary>
        public int AabbScale => NerfDatasetCreator.AabbScale.ForRadius(TargetReach);

        /// <summary>
        /// Every view, made on demand from the settings (<see cref="PlannedViewList"/>): the plan holds no list of views,
        /// so its memory does not grow with their number. Each read makes a new <see cref="PlannedView"/> with the same values.
        /// </summary>
        public IReadOnlyList<PlannedView> Views => _views;

        /// <summary>The time span of a dynamic capture (<see cref="TimePlanning"/>); null for a static one.</summary>
        public TimeRange Time { get; }

        /// <summary>The views of one split, in order, made on demand like <see cref="Views"/>.</summary>
        public IReadOnlyList<PlannedView> ViewsOf(DatasetSplit split) => _views.OfSplit(split);

        /// <summary>
        /// The same plan holding only the views <paramref name="keep"/> accepts, in the same order — a shard's share.
        /// Its transforms files list just those frames; settings, distance and intrinsics are the whole plan's.
        /// </summary>
        public CapturePlan Only(Func<PlannedView, bool> keep) =>
            new CapturePlan(Settings, Target, Distance, Intrinsics, Normalisation, Warnings, _views.Where(keep), Time);

        /// <summary>nerf_synthetic's <c>rotation</c> key for a split (ignored by every loader): the formation's azimuth step.</summary>
        public double RotationOf(DatasetSplit split)
        {
            var s = Settings.Split(split);
            return s.Source != null && !s.Source.IsFormation ? 0 : s.Formation.AzimuthStepRadians(s.Count);
        }

        /// <summary>
        /// Every problem that stops these settings from being planned for this target: the settings' own problems
        /// plus, when the target's bounds are known, cameras inside its bounding sphere or clip planes cutting it.
        /// </summary>
        public static IReadOnlyList<ValidationProblem> Check(DatasetSettings settings, PlanTarget target)
        {
            var problems = new List<ValidationProblem>(SettingsValidator.Validate(settings));
            if (!target.Centre.IsFinite)
                problems.Add(new ValidationProblem("target", target.Centre.ToString(), "has a position that is not finite.", "Move the target to a finite position."));
            if (double.IsNaN(target.BoundingRadius) || double.IsInfinity(target.BoundingRadius) || target.BoundingRadius < 0)
                problems.Add(new ValidationProblem("target", ValidationProblem.Format(target.BoundingRadius), "has bounds that are not a finite size.", "Check the target's renderers."));
            if (problems.Count > 0) return problems;
            settings = CameraSourcePlanning.Resolved(settings, out _, problems);
            if (problems.Count > 0) return problems;
            problems.AddRange(TimePlanning.Check(settings, target.ClipLengthSeconds));
            problems.AddRange(ShutterPlanning.Check(settings, target.ClipLengthSeconds));
            if (problems.Count > 0 || !CameraSourcePlanning.AnyFormation(settings)) return problems;

            if (settings.AutoDistance && !target.HasBounds)
            {
                problems.Add(target.IsHeadless
                    ? new ValidationProblem("distance", "\"auto\"", "needs the target's bounds, which only Unity measures: the headless tool plans for a target at the origin of unknown size.",
                        "Give the distance as a number (about 3.5 × the target's radius keeps it in every loader's range; the window's Target step shows the suggestion), or capture with \"auto\" in Unity.")
                    : new ValidationProblem("distance", "\"auto\"", "needs the target's bounds, which are unknown here.",
                        "Pick a target with renderers, or give the distance as a number."));
                return problems;
            }
            if (settings.Normalisation == NormalisationMode.FitTargetRadius && !target.HasBounds)
                problems.Add(new ValidationProblem("normalisation", "\"" + NormalisationModes.Name(settings.Normalisation) + "\"",
                    "scales the target to a chosen radius, which needs the target's bounds; they are unknown here.",
                    target.IsHeadless
                        ? "The headless tool knows no target: use \"recentre\" or \"nerf-synthetic\" here, or capture with \"fit-radius\" in Unity."
                        : "Pick a target with renderers, or use \"recentre\" or \"nerf-synthetic\"."));
            if (!target.HasBounds) return problems;
            var distance = ResolveDistance(settings, target);
            var b = target.BoundingRadius;
            var near = settings.Camera.NearClip;
            var far = settings.Camera.FarClip;
            var shown = ValidationProblem.Format(distance);
            if (distance <= b)
                problems.Add(new ValidationProblem("distance", shown,
                    "puts the cameras inside the target's bounding sphere (radius " + ValidationProblem.Format(b) + ").",
                    "Use a distance above " + ValidationProblem.Format(b) + ", or \"auto\"."));
            else if (distance - b <= near)
                problems.Add(new ValidationProblem("camera.nearClip", ValidationProblem.Format(near),
                    "would cut the target: its nearest side is " + ValidationProblem.Format(distance - b) + " from the cameras.",
                    "Lower the near clip below " + ValidationProblem.Format(distance - b) + " or increase the distance."));
            if (distance + b >= far)
                problems.Add(new ValidationProblem("camera.farClip", ValidationProblem.Format(far),
                    "would cut the target: its far side is " + ValidationProblem.Format(distance + b) + " from the cameras.",
                    "Raise the far clip above " + ValidationProblem.Format(distance + b) + " or decrease the distance."));
            return problems;
        }

        /// <summary>The distance the plan uses: the fixed one, or <see cref="AutoDistanceRule"/> on the target's bounds.</summary>
        public static double ResolveDistance(DatasetSettings settings, PlanTarget target) =>
            settings.AutoDistance
                ? AutoDistanceRule.Distance(target.BoundingRadius, settings.Camera.VerticalFovDegrees, settings.Width, settings.Height, settings.AutoDistanceMargin)
                : settings.Distance;

        /// <summary>Builds the plan, or throws <see cref="InvalidParameterException"/> with every problem of <see cref="Check"/>.</summary>
        public static CapturePlan Build(DatasetSettings settings, PlanTarget target)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            var problems = Check(settings, target);
            if (problems.Count > 0) throw new InvalidParameterException(problems);

            var copy = CameraSourcePlanning.Resolved(settings, out var imported);
            var distance = ResolveDistance(copy, target);
            var normalisation = SceneNormalisation.ForTarget(copy.Normalisation, target.Centre, target.BoundingRadius, distance, copy.NormalisedTargetRadius);
            var time = TimePlanning.Resolve(copy, target.ClipLengthSeconds);
            // Each split's placement, not its views: every view is made again when it is read (PlannedViewList).
            var splits = new PlanSplitViews[DatasetSplits.All.Count];
            var offset = 0;
            foreach (var split in DatasetSplits.All)
            {
                imported.TryGetValue(split, out var cameras);
                var s = new PlanSplitViews(copy, split, offset, cameras, target.Centre, distance, normalisation, time);
                splits[(int)split] = s;
                offset += s.Count;
            }
            var views = new PlannedViewList(splits);
            var framing = FramingWarning.For(copy, target, distance, copy.Intrinsics());
            var warnings = PlanWarnings.For(copy, target, normalisation, PosesOf(splits))
                .Concat(framing == null ? new ValidationProblem[0] : new[] { framing })
                .Concat(CameraSourcePlanning.Warnings(copy, copy.Intrinsics(), imported))
                .Concat(BlurLengthWarning.For(copy, target, copy.Intrinsics(), views)).ToList();
            return new CapturePlan(copy, target, distance, copy.Intrinsics(), normalisation, warnings, views, time);
        }

        // A plain loop: this runs once per view, up to 300 000 times.
        static IEnumerable<UnityPose> PosesOf(PlanSplitViews[] splits)
        {
            foreach (var s in splits)
                for (var i = 0; i < s.Count; i++) yield return s.PoseAt(i);
        }
    }
}
