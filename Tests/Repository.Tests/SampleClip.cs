using System;
using System.Collections.Generic;
using System.Linq;
using YamlDotNet.RepresentationModel;

namespace NerfDatasetCreator.Repository.Tests
{
    /// <summary>
    /// The sample's hand-written legacy clip (Assets/Samples/NeRFSample/SlideAndTurn.anim) as data: its curves read
    /// from the YAML and evaluated the way an AnimationCurve is, so tests can hold the file to the motion it is meant
    /// to have.
    /// </summary>
    sealed class SampleClip
    {
        public const string AnimatedTarget = "NeRFAnimatedTarget";
        public const string CubeName = "Cube";

        public static string ClipPath => RepositoryPaths.Combine("Assets", "Samples", "NeRFSample", "SlideAndTurn.anim");
        public static string ScenePath => RepositoryPaths.Combine("Assets", "Samples", "NeRFSample", "NeRFSample.unity");

        /// <summary>One keyframe of one component: time, value and the two slopes (per second).</summary>
        public readonly struct Key
        {
            public Key(double time, double value, double inSlope, double outSlope)
            {
                Time = time;
                Value = value;
                InSlope = inSlope;
                OutSlope = outSlope;
            }

            public double Time { get; }
            public double Value { get; }
            public double InSlope { get; }
            public double OutSlope { get; }

            public override string ToString() => "(t " + Time + ", v " + Value + ", in " + InSlope + ", out " + OutSlope + ")";
        }

        public UnityYaml File { get; }
        public YamlMappingNode Clip { get; }

        SampleClip(UnityYaml file)
        {
            File = file;
            Clip = file.Objects.Single().Body;
        }

        public static SampleClip Load() => new SampleClip(UnityYaml.Load(ClipPath));

        /// <summary>The runtime Vector3 curve of <paramref name="section"/> (m_PositionCurves, m_EulerCurves…) at <paramref name="path"/>, one key list per axis.</summary>
        public List<Key>[] VectorCurve(string section, string path)
        {
            var curve = UnityYaml.Sequence(Clip, section).Cast<YamlMappingNode>().Single(c => UnityYaml.Text(c, "path") == path);
            var keys = UnityYaml.Sequence(UnityYaml.Map(curve, "curve"), "m_Curve").Cast<YamlMappingNode>().ToList();
            return Enumerable.Range(0, 3).Select(axis => keys.Select(k => new Key(
                UnityYaml.Number(k, "time"),
                UnityYaml.Vector3(UnityYaml.Node(k, "value"))[axis],
                UnityYaml.Vector3(UnityYaml.Node(k, "inSlope"))[axis],
                UnityYaml.Vector3(UnityYaml.Node(k, "outSlope"))[axis])).ToList()).ToArray();
        }

        /// <summary>The editor float curve (m_EditorCurves) of <paramref name="attribute"/> at <paramref name="path"/>, with each key's tangentMode.</summary>
        public List<(Key Key, int TangentMode)> EditorCurve(string attribute, string path)
        {
            var curve = UnityYaml.Sequence(Clip, "m_EditorCurves").Cast<YamlMappingNode>()
                .Single(c => UnityYaml.Text(c, "attribute") == attribute && UnityYaml.Text(c, "path") == path);
            return UnityYaml.Sequence(UnityYaml.Map(curve, "curve"), "m_Curve").Cast<YamlMappingNode>().Select(k => (
                new Key(UnityYaml.Number(k, "time"), UnityYaml.Number(k, "value"), UnityYaml.Number(k, "inSlope"), UnityYaml.Number(k, "outSlope")),
                (int)UnityYaml.Number(k, "tangentMode"))).ToList();
        }

        public double StartTime => UnityYaml.Number(UnityYaml.Map(Clip, "m_AnimationClipSettings"), "m_StartTime");
        public double StopTime => UnityYaml.Number(UnityYaml.Map(Clip, "m_AnimationClipSettings"), "m_StopTime");

        /// <summary>
        /// An AnimationCurve's value at <paramref name="t"/> (weightedMode 0): between keys a and b the cubic Hermite
        /// spline through their values with a's out-slope and b's in-slope (Scripting API: Keyframe.inTangent /
        /// outTangent, "the incoming/outgoing tangent affects the slope of the curve"); outside the keys the end
        /// value, as m_PreInfinity / m_PostInfinity 2 (clamp) say.
        /// </summary>
        public static double Evaluate(IReadOnlyList<Key> keys, double t)
        {
            if (t <= keys[0].Time) return keys[0].Value;
            if (t >= keys[keys.Count - 1].Time) return keys[keys.Count - 1].Value;
            var i = 0;
            while (t > keys[i + 1].Time) i++;
            var a = keys[i];
            var b = keys[i + 1];
            var dt = b.Time - a.Time;
            var s = (t - a.Time) / dt;
            double s2 = s * s, s3 = s2 * s;
            return (2 * s3 - 3 * s2 + 1) * a.Value + (s3 - 2 * s2 + s) * dt * a.OutSlope +
                   (-2 * s3 + 3 * s2) * b.Value + (s3 - s2) * dt * b.InSlope;
        }

        public static double[] Evaluate(IReadOnlyList<Key>[] curve, double t) => curve.Select(axis => Evaluate(axis, t)).ToArray();

        /// <summary>The cube's local position and Euler angles (degrees) at <paramref name="t"/> seconds, from the runtime curves.</summary>
        public (double[] Position, double[] Euler) Pose(double t) =>
            (Evaluate(VectorCurve("m_PositionCurves", CubeName), t), Evaluate(VectorCurve("m_EulerCurves", CubeName), t));

        /// <summary>
        /// The motion the sample is meant to have, derived by hand: over 2 s the cube slides x from −0.6 to 0.6
        /// (0.6 per second), rises y from 0.4 to 0.8 at 1 s and back to 0.4 (±0.4 per second), stays at z 0, and
        /// turns its yaw from 0° to 90° (45° per second), all linear between the keys.
        /// </summary>
        public static (double[] Position, double[] Euler) IntendedPose(double t)
        {
            t = Math.Max(0, Math.Min(2, t));
            var y = t <= 1 ? 0.4 + 0.4 * t : 1.2 - 0.4 * t;
            return (new[] { -0.6 + 0.6 * t, y, 0 }, new[] { 0, 45 * t, 0 });
        }
    }
}
