using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What the SLAM layouts (<see cref="ReplicaExport"/>, <see cref="TumRgbdExport"/>) share: the sequence is the
    /// train split's frames in time order (a monocular dynamic capture: an animated or imported camera, one view per
    /// time step), each with its <c>time_seconds</c> and its depth; RGB over the protocol background (every SLAM reader
    /// drops alpha: SplaTAM's imageio, Gaussian-SLAM's cv2.imread, and MonoGS's PIL array would keep a 4th channel
    /// its 3-channel loss cannot take); poses as camera-to-world in OpenCV camera axes (x right, y down, looking along +z),
    /// the convention SplaTAM and Gaussian-SLAM use as read and MonoGS inverts (Documentation~/maintainers/layouts-slam.md).
    /// </summary>
    public static class SlamSequence
    {
        /// <summary>One frame of the sequence with its time in seconds.</summary>
        public sealed class Frame
        {
            public ExportFrame Source;
            public double Seconds;
        }

        /// <summary>
        /// The train split's frames sorted by <c>time_seconds</c>, or refused with one line naming what is missing: time,
        /// depth, a second frame, or one camera per time.
        /// </summary>
        public static IReadOnlyList<Frame> Read(ExportScene scene, ExportTarget target, List<ValidationProblem> warnings)
        {
            var name = "--to " + ExportTargets.Name(target);
            var train = scene.Split("train").ToList();
            var untimed = train.Where(f => !f.Timing.Seconds.HasValue || double.IsNaN(f.Timing.Seconds.Value) || double.IsInfinity(f.Timing.Seconds.Value)).ToList();
            if (train.Count == 0 || untimed.Count > 0)
                throw Refuse("time_seconds", train.Count == 0 ? "no train frames" : untimed.Count + " of " + train.Count + " train frames without it (first: " + untimed[0].ImagePath + ")",
                    "is what " + name + " takes each frame's timestamp from: a SLAM sequence is one moving camera in time, and this dataset has no time.",
                    "Capture with time.mode \"monocular\" and an animated or imported camera for the train split (Documentation~/dynamic-capture.md).");
            var frames = train.Select(f => new Frame { Source = f, Seconds = f.Timing.Seconds.Value }).OrderBy(f => f.Seconds).ToList();
            for (var i = 1; i < frames.Count; i++)
                if (frames[i].Seconds == frames[i - 1].Seconds)
                    throw Refuse("time_seconds", Number(frames[i].Seconds) + " s (" + frames[i - 1].Source.ImagePath + " and " + frames[i].Source.ImagePath + ")",
                        "is the time of two train frames: a multi-view capture films several cameras at each time, and a SLAM sequence is one camera.",
                        "Capture with time.mode \"monocular\" (one train view per time step).");
            if (frames.Count < 2)
                throw Refuse("splits.train.count", "1", "frame is no sequence: the readers track the camera from frame to frame (and numpy reads a one-line list as a row, not a table).",
                    "Capture at least 2 train views.");
            var noDepth = train.Where(f => f.DepthPath == null).ToList();
            if (noDepth.Count > 0)
                throw Refuse("depth_path", noDepth.Count + " of " + train.Count + " train frames without it (first: " + noDepth[0].ImagePath + ")",
                    (noDepth[0].UnusableDepth != null ? noDepth[0].UnusableDepth.Value + " " + noDepth[0].UnusableDepth.Reason + " " : "") +
                    name + " is an RGB-D sequence: SplaTAM, MonoGS and Gaussian-SLAM read a depth image with every colour image.",
                    "Capture with depth in the train split (splits.train.depth \"png\").");
            foreach (var split in new[] { "val", "test" })
            {
                var count = scene.Split(split).Count();
                if (count > 0)
                    warnings.Add(new ValidationProblem(split, count + " frames", "are not exported: the sequence is the train split's camera path in time, which the SLAM methods track and also evaluate on.",
                        "Nothing to do; to include views, capture them in the train split."));
            }
            return frames;
        }

        /// <summary>OpenGL camera-to-world (our frames) → OpenCV camera axes: the y and z columns negated.</summary>
        public static Matrix4x4d CameraToWorldOpenCv(Matrix4x4d cameraToWorldOpenGl) => cameraToWorldOpenGl * Matrix4x4d.FromRowMajor(
            1, 0, 0, 0,
            0, -1, 0, 0,
            0, 0, -1, 0,
            0, 0, 0, 1);

        /// <summary>The frame's colour as 8-bit RGB over (<paramref name="r"/>, <paramref name="g"/>, <paramref name="b"/>) (<see cref="AlphaCompositing"/>).</summary>
        public static byte[] Rgb(ExportScene scene, ExportFrame frame, (string Name, byte R, byte G, byte B) background, out int width, out int height)
        {
            var image = ExportRgb.Decode(Path.Combine(scene.RootDirectory, frame.ImagePath), frame.ImagePath);
            width = image.Width;
            height = image.Height;
            return ExportRgb.Rgb(image, (background.R, background.G, background.B));
        }

        /// <summary>
        /// The frame's depth re-quantised to <paramref name="perUnit"/> steps per output unit, rounded to nearest; 0
        /// (no hit) stays 0, and a depth the 16-bit code cannot hold (above 65535 / perUnit) is written as 0 — no
        /// measurement, which the readers skip — rather than as a false wall at the range's end; those pixels are counted.
        /// </summary>
        public static ushort[] Depth(ExportScene scene, ExportFrame frame, double perUnit, ref long beyondRange, out int width, out int height)
        {
            var source = PngGray16Reader.Read(Path.Combine(scene.RootDirectory, frame.DepthPath), out width, out height);
            var output = new ushort[source.Length];
            for (var i = 0; i < source.Length; i++)
            {
                if (source[i] == 0) continue;
                var code = Math.Round(source[i] * scene.DepthUnitScale * perUnit, MidpointRounding.AwayFromZero);
                if (code > ushort.MaxValue) beyondRange++;
                else output[i] = (ushort)code;
            }
            return output;
        }

        /// <summary>The warning for depth pixels beyond a format's range, or null when there are none.</summary>
        public static ValidationProblem RangeWarning(string folder, long beyondRange, long pixels, double perUnit, string format)
        {
            if (beyondRange == 0) return null;
            return new ValidationProblem(folder, beyondRange + " of " + pixels + " depth pixels",
                "are farther than " + Number(Math.Floor(ushort.MaxValue / perUnit * 1000) / 1000) + " output units, the most " + format + "'s 16-bit depth holds at " + Number(perUnit) +
                " steps per unit; they are written as 0 (no measurement, which the readers skip).",
                "Capture with a normalisation that brings the scene nearer (e.g. \"nerf-synthetic\"), or ignore if only far background is lost.");
        }

        /// <summary>Invariant round-trip text of a number (what the readers' float() and numpy parse back exactly).</summary>
        public static string Number(double value)
        {
            if (value == 0) value = 0; // no "-0"
            return value.ToString("R", CultureInfo.InvariantCulture);
        }

        internal static InvalidParameterException Refuse(string field, string value, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem(field, value, reason, fix) });
    }
}
