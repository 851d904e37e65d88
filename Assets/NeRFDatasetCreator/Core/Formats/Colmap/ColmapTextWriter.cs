using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// COLMAP's text model (<c>sparse/0/cameras.txt</c>, <c>images.txt</c>, <c>points3D.txt</c>) as COLMAP writes it and
    /// as 3D Gaussian Splatting's COLMAP reader parses it. One shared PINHOLE camera (fx fy cx cy, pixel coordinates
    /// with the top-left image corner at 0 — the same convention as <see cref="CameraIntrinsics"/>). Each image line
    /// holds the world-to-camera rotation as a Hamilton quaternion (QW QX QY QZ) and translation in COLMAP's camera
    /// axes (x right, y down, looking along +z): the OpenGL c2w with its y and z axes negated, inverted. The second
    /// line of each image holds its 2D observations when the model has tracks (<see cref="ColmapModel"/>), else it is empty. Image names are single tokens: 3DGS splits lines on
    /// whitespace and opens <c>&lt;source&gt;/images/&lt;basename of NAME&gt;</c>, so split folders are flattened into
    /// unique names (<see cref="ImageName"/>).
    /// </summary>
    public static class ColmapTextWriter
    {
        public const string SparseFolder = "sparse/0";
        public const string ImagesFolder = "images";

        /// <summary><c>train/r_0.png</c> → <c>train_r_0.png</c>: unique across splits, no folder, no whitespace.</summary>
        public static string ImageName(string relativeImagePath) => ExportPaths.Normalise(relativeImagePath).Replace('/', '_');

        /// <summary>The COLMAP names of the frames, checked to be unique and free of whitespace.</summary>
        public static IReadOnlyList<string> ImageNames(IReadOnlyList<ExportFrame> frames)
        {
            var names = frames.Select(f => ImageName(f.ImagePath)).ToList();
            var problems = new List<ValidationProblem>();
            foreach (var bad in names.Where(n => n.Any(char.IsWhiteSpace)))
                problems.Add(new ValidationProblem("file_path", bad, "contains whitespace, which COLMAP's text format cannot hold in an image name.", "Rename the images without spaces."));
            foreach (var dup in names.GroupBy(n => n).Where(g => g.Count() > 1))
                problems.Add(new ValidationProblem("file_path", dup.Key, $"is the flattened name of {dup.Count()} images; COLMAP needs unique names.", "Give every image a distinct path."));
            InvalidParameterException.ThrowIfAny(problems.ToArray());
            return names;
        }

        public static string CamerasText(CameraIntrinsics k) => CamerasText(k, null);

        /// <summary>
        /// cameras.txt with <paramref name="lens"/>'s model (OPENCV, FULL_OPENCV or OPENCV_FISHEYE and its parameters in
        /// models.h's order, <see cref="LensDistortion.ColmapParams"/>), or PINHOLE when it is null.
        /// </summary>
        public static string CamerasText(CameraIntrinsics k, LensDistortion lens)
        {
            var sb = new StringBuilder();
            sb.Append("# Camera list with one line of data per camera:\n");
            sb.Append("#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n");
            sb.Append("# Number of cameras: 1\n");
            var parameters = lens == null ? new[] { k.FlX, k.FlY, k.Cx, k.Cy } : lens.ColmapParams(k);
            sb.Append("1 ").Append(lens == null ? "PINHOLE" : lens.ColmapModelName).Append(' ').Append(I(k.Width)).Append(' ').Append(I(k.Height));
            foreach (var p in parameters) sb.Append(' ').Append(R(p));
            sb.Append('\n');
            return sb.ToString(); // numbers went through R() and I(), both invariant
        }

        public static string ImagesText(IReadOnlyList<ExportFrame> frames, IReadOnlyList<string> names)
        {
            if (names.Count != frames.Count) throw new ArgumentException("One name per frame is needed.", nameof(names));
            var poses = frames.Select(f => ColmapPose.FromCameraToWorld(f.CameraToWorld)).ToList();
            var writer = new StringWriter(CultureInfo.InvariantCulture);
            WriteImages(writer, names, poses, null);
            return writer.ToString();
        }

        /// <summary>Points with empty tracks; with no points, only the header (valid COLMAP, but see the converter's warning).</summary>
        public static string Points3DText(IReadOnlyList<CloudPoint> points)
        {
            var writer = new StringWriter(CultureInfo.InvariantCulture);
            WritePoints3D(writer, points ?? Array.Empty<CloudPoint>(), null);
            return writer.ToString();
        }

        /// <summary><c>images.txt</c> of <paramref name="model"/>: each image line, then its POINTS2D as X Y POINT3D_ID triples (empty without tracks).</summary>
        public static void WriteImages(TextWriter writer, ColmapModel model) => WriteImages(writer, model.Names, model.Poses, model);

        /// <summary><c>points3D.txt</c> of <paramref name="model"/>: each point, its ERROR and its TRACK as IMAGE_ID POINT2D_IDX pairs.</summary>
        public static void WritePoints3D(TextWriter writer, ColmapModel model) => WritePoints3D(writer, model.Points, model);

        static void WriteImages(TextWriter w, IReadOnlyList<string> names, IReadOnlyList<ColmapPose> poses, ColmapModel model)
        {
            w.Write("# Image list with two lines of data per image:\n");
            w.Write("#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n");
            w.Write("#   POINTS2D[] as (X, Y, POINT3D_ID)\n");
            w.Write("# Number of images: " + I(names.Count) + ", mean observations per image: " + R(model?.MeanObservationsPerImage ?? 0) + "\n");
            for (var i = 0; i < names.Count; i++)
            {
                var pose = poses[i];
                var q = pose.Rotation;
                var t = pose.Translation;
                w.Write(I(i + 1)); w.Write(' ');
                w.Write(R(q.W)); w.Write(' '); w.Write(R(q.X)); w.Write(' '); w.Write(R(q.Y)); w.Write(' '); w.Write(R(q.Z)); w.Write(' ');
                w.Write(R(t.X)); w.Write(' '); w.Write(R(t.Y)); w.Write(' '); w.Write(R(t.Z)); w.Write(" 1 ");
                w.Write(names[i]); w.Write('\n');
                var observed = model?.Observations[i];
                if (observed != null)
                    for (var k = 0; k < observed.Length; k++)
                    {
                        pose.Project(model.Points[observed[k]].Position, model.Camera, model.Lens, out var x, out var y);
                        if (k > 0) w.Write(' ');
                        w.Write(R(x)); w.Write(' '); w.Write(R(y)); w.Write(' '); w.Write(I(observed[k] + 1));
                    }
                w.Write('\n'); // the POINTS2D line, empty without observations
            }
        }

        static void WritePoints3D(TextWriter w, IReadOnlyList<CloudPoint> points, ColmapModel model)
        {
            w.Write("# 3D point list with one line of data per point:\n");
            w.Write("#   POINT3D_ID, X, Y, Z, R, G, B, ERROR, TRACK[] as (IMAGE_ID, POINT2D_IDX)\n");
            w.Write("# Number of points: " + I(points.Count) + ", mean track length: " + R(model?.MeanTrackLength ?? 0) + "\n");
            for (var i = 0; i < points.Count; i++)
            {
                var p = points[i];
                w.Write(I(i + 1)); w.Write(' ');
                w.Write(R(p.Position.X)); w.Write(' '); w.Write(R(p.Position.Y)); w.Write(' '); w.Write(R(p.Position.Z)); w.Write(' ');
                w.Write(I(p.Red)); w.Write(' '); w.Write(I(p.Green)); w.Write(' '); w.Write(I(p.Blue)); w.Write(' ');
                w.Write(R(model?.Error(i) ?? 0));
                if (model != null)
                    for (var e = model.TrackStart[i]; e < model.TrackStart[i + 1]; e++)
                    {
                        w.Write(' '); w.Write(I(model.TrackImage[e] + 1)); w.Write(' '); w.Write(I(model.TrackPoint2D[e]));
                    }
                w.Write('\n');
            }
        }

        /// <summary>
        /// COLMAP's extrinsics of an OpenGL camera-to-world matrix: C = c2w·diag(1, −1, −1) (OpenCV axes), then
        /// R = Cᵀ (world-to-camera rotation), t = −R·centre. The quaternion has w ≥ 0.
        /// </summary>
        public static void WorldToCamera(Matrix4x4d cameraToWorldOpenGl, out Quaterniond rotation, out Vector3d translation)
        {
            // Re-orthonormalise, keeping the viewing axis exact: float32 sources such as nerf_synthetic are
            // orthonormal only to ~1e-7, and a quaternion of a non-rotation would tilt the view by as much.
            var z = (-cameraToWorldOpenGl.Column(2)).Normalized();
            var right = cameraToWorldOpenGl.Column(0);
            var x = (right - Vector3d.Dot(right, z) * z).Normalized();
            var y = Vector3d.Cross(z, x); // OpenCV is right-handed: x × y = z
            var centre = cameraToWorldOpenGl.Translation;
            // Rows of R are the OpenCV camera axes in world coordinates; FromBasis takes R's columns.
            var c0 = new Vector3d(x.X, y.X, z.X);
            var c1 = new Vector3d(x.Y, y.Y, z.Y);
            var c2 = new Vector3d(x.Z, y.Z, z.Z);
            rotation = Quaterniond.FromBasis(c0, c1, c2);
            // t from the quaternion's own (exactly orthonormal) rotation, so that the reader's centre −Rᵀt is the
            // written centre even when the input rotation is only float32-orthonormal (nerf_synthetic: ~1e-7).
            translation = -rotation.Rotate(centre);
        }

        static string R(double v)
        {
            if (double.IsNaN(v) || double.IsInfinity(v)) throw new ArgumentException("COLMAP files cannot hold " + v + ".");
            if (v == 0) v = 0; // "-0" is valid but reads like a sign error
            return v.ToString("R", CultureInfo.InvariantCulture);
        }

        static string I(int v) => v.ToString(CultureInfo.InvariantCulture);
    }
}
