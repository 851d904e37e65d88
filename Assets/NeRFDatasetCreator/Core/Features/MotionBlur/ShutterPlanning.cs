using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Each view's <see cref="ShutterMotion"/> for <see cref="CapturePlan"/>. The interval is centred on the planned
    /// pose, so <c>transform_matrix</c> is unchanged by motion blur:
    /// <list type="bullet">
    /// <item><b>path</b>: the camera's velocity at a split's camera c is the central difference of its neighbours in the
    /// split's order, (p[c+1] − p[c−1])/2 and log(R[c+1]·R[c−1]⁻¹)/2 (one-sided at the ends, none for a single camera);
    /// the shutter covers <c>shutter</c> of that spacing.</item>
    /// <item><b>shake</b>: a seeded random direction and axis per view (<c>SeededRandom.Derive(seed, "motionBlur/&lt;split&gt;")</c>),
    /// moving the centre <c>shakeDistance</c> and turning <c>shakeDegrees</c> over the shutter.</item>
    /// <item><b>still</b>: no camera motion.</item>
    /// </list>
    /// In a dynamic capture the content is shown over [t − s·Δt/2, t + s·Δt/2], Δt the time step, t the view's time.
    /// </summary>
    public sealed class ShutterPlanning
    {
        readonly MotionBlurSettings _settings;
        readonly IReadOnlyList<UnityPose> _cameras;
        readonly SceneNormalisation _normalisation;
        readonly double _step;
        readonly long _seed;

        ShutterPlanning(MotionBlurSettings settings, IReadOnlyList<UnityPose> cameras, SceneNormalisation normalisation, TimeRange time, long seed)
        {
            _settings = settings;
            _cameras = cameras;
            _normalisation = normalisation;
            _step = time == null ? 0 : (time.EndSeconds - time.StartSeconds) / (time.Steps - 1);
            _seed = seed;
        }

        /// <summary>Whether these settings blur (the section is on).</summary>
        public static bool IsOn(DatasetSettings settings) => settings?.MotionBlur != null && settings.MotionBlur.Enabled;

        /// <summary>The planning of one split whose cameras, in the split's order, are <paramref name="cameras"/>; null when blur is off.</summary>
        public static ShutterPlanning ForSplit(DatasetSettings settings, DatasetSplit split, IReadOnlyList<UnityPose> cameras, SceneNormalisation normalisation, TimeRange time)
        {
            if (!IsOn(settings)) return null;
            return new ShutterPlanning(settings.MotionBlur, cameras, normalisation, time,
                SeededRandom.Derive(settings.Seed, "motionBlur/" + DatasetSplits.Name(split)));
        }

        /// <summary>
        /// The shutter's problems that need the resolved time range: a dynamic capture whose first view's shutter would
        /// open before content time 0 (Unity's clips have no content there).
        /// </summary>
        public static IReadOnlyList<ValidationProblem> Check(DatasetSettings settings, double clipLengthSeconds)
        {
            var problems = new List<ValidationProblem>();
            if (!IsOn(settings) || settings.Time == null || !settings.Time.Enabled) return problems;
            TimeRange range;
            try
            {
                range = TimePlanning.Resolve(settings, clipLengthSeconds);
            }
            catch (InvalidParameterException)
            {
                return problems; // TimePlanning reports it
            }
            if (range == null) return problems;
            var half = settings.MotionBlur.Shutter * (range.EndSeconds - range.StartSeconds) / (range.Steps - 1) / 2;
            if (range.StartSeconds - half < -1e-12)
                problems.Add(new ValidationProblem("time.start", ValidationProblem.Format(range.StartSeconds),
                    "is less than half a shutter (" + ValidationProblem.Format(half) + " s = motionBlur.shutter × time step / 2) after content time 0, so the first view's shutter would open before the content exists.",
                    "Start at " + ValidationProblem.Format(half) + " s or later, or shorten motionBlur.shutter."));
            return problems;
        }

        /// <summary>
        /// The motion of the split's view <paramref name="view"/>, which uses the split's camera <paramref name="camera"/> at
        /// <paramref name="time"/>. A shake takes the split's random draws 4·view … 4·view + 3, reached directly
        /// (<see cref="SeededRandom.AtDraw"/>): a plan makes its views on demand, in any order and on several threads.
        /// </summary>
        public ShutterMotion Motion(int camera, ViewTime? time, int view)
        {
            var mid = _cameras[camera];
            var translation = Vector3d.Zero;
            var rotation = Vector3d.Zero;
            if (_settings.Camera == ShutterCameraMotion.Path && _cameras.Count > 1)
            {
                var previous = Math.Max(camera - 1, 0);
                var next = Math.Min(camera + 1, _cameras.Count - 1);
                var span = next - previous;
                var s = _settings.Shutter / span;
                translation = (_cameras[next].Position - _cameras[previous].Position) * s;
                var turn = _cameras[next].Rotation * PoseInterpolation.Inverse(_cameras[previous].Rotation);
                rotation = PoseInterpolation.ToRotationVector(turn.Normalized()) * s;
            }
            else if (_settings.Camera == ShutterCameraMotion.Shake)
            {
                // The same draws as drawing for every view in plan order, so the same seed gives the same shakes.
                var random = SeededRandom.AtDraw(_seed, 4L * view);
                translation = UnitVector(random) * _settings.ShakeDistance;
                rotation = UnitVector(random) * (_settings.ShakeDegrees * Math.PI / 180);
            }
            double? open = null, close = null;
            if (time.HasValue)
            {
                var half = _settings.Shutter * _step / 2;
                open = time.Value.Seconds - half;
                close = time.Value.Seconds + half;
            }
            return ShutterMotion.Centred(mid, translation, rotation, _normalisation, open, close);
        }

        /// <summary>A direction uniform on the sphere (z uniform in [−1, 1], azimuth uniform).</summary>
        static Vector3d UnitVector(SeededRandom random)
        {
            var z = 2 * random.NextDouble() - 1;
            var phi = 2 * Math.PI * random.NextDouble();
            var r = Math.Sqrt(Math.Max(0, 1 - z * z));
            return new Vector3d(r * Math.Cos(phi), r * Math.Sin(phi), z);
        }
    }
}
