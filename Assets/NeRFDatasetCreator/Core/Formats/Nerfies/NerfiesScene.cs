using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>scene.json</c>: <c>center</c>, <c>scale</c>, <c>near</c>, <c>far</c> (nerfies/datasets/nerfies.py:29–54; DyCheck
    /// datasets/nerfies.py:64–72). The readers move every camera to (position − center)·scale (nerfies/datasets/core.py:102–105,
    /// DyCheck's translate/rescale) and sample rays between near and far, which are in those scaled units along unit ray
    /// directions (camera.py:241–242, 266–267). The rules are Nerfies' capture notebook's
    /// (notebooks/Nerfies_Capture_Processing.ipynb, "Compute scene center and scale" and "Save scene information"):
    /// center = the middle of the bounding box of the scene points and the camera centres, scale = 1 / its diagonal;
    /// the notebook estimates near and far from SfM points, here they are exact: the least and greatest distance along
    /// any pixel-centre ray to a depth-map hit (z·√(1 + x² + y²), x = (i + ½ − cx)/fx, y = (j + ½ − cy)/fy), times scale.
    /// The scene points are the target's reach (a cube of ±reach about the output origin). Without depth maps, near and
    /// far bound that sphere from the cameras instead (said in a warning).
    /// 4DGaussians ignores center and scale (it reads orientation and position as written, hyper_loader.py:161–162).
    /// </summary>
    public sealed class NerfiesScene
    {
        public Vector3d Center { get; private set; }
        public double Scale { get; private set; }

        /// <summary>Near and far in output units (unscaled): scene.json holds them times <see cref="Scale"/>.</summary>
        public double Near { get; private set; }
        public double Far { get; private set; }
        public Vector3d Low { get; private set; }
        public Vector3d High { get; private set; }

        /// <summary>Whether near and far come from the depth maps (exact) rather than from the target's reach.</summary>
        public bool FromDepth { get; private set; }

        public JObject ToJson() => new JObject
        {
            ["scale"] = Scale,
            ["center"] = Row(Center),
            ["bbox"] = new JArray(Row(Low), Row(High)),
            ["near"] = Near * Scale,
            ["far"] = Far * Scale,
        };

        static JArray Row(Vector3d v) => new JArray(v.X, v.Y, v.Z);

        /// <summary>The scene of <paramref name="views"/>; refuses (one line) when there is neither depth nor a recorded reach.</summary>
        public static NerfiesScene Of(ExportScene scene, IReadOnlyList<NerfiesView> views, string target, List<ValidationProblem> warnings)
        {
            var centres = views.Select(v => v.Frame.Centre).ToList();
            var reach = scene.TargetReach;
            var points = new List<Vector3d>(centres);
            if (reach.HasValue)
            {
                points.Add(new Vector3d(-reach.Value, -reach.Value, -reach.Value));
                points.Add(new Vector3d(reach.Value, reach.Value, reach.Value));
            }
            var low = new Vector3d(points.Min(p => p.X), points.Min(p => p.Y), points.Min(p => p.Z));
            var high = new Vector3d(points.Max(p => p.X), points.Max(p => p.Y), points.Max(p => p.Z));
            var diagonal = Vector3d.Distance(low, high);
            var result = new NerfiesScene { Low = low, High = high, Center = (low + high) / 2, Scale = diagonal > 0 ? 1 / diagonal : 1 };

            var noDepth = views.FirstOrDefault(v => v.Frame.DepthPath == null);
            if (noDepth == null && DepthRange(scene, views, out var near, out var far))
            {
                result.Near = near;
                result.Far = far;
                result.FromDepth = true;
                return result;
            }
            if (!reach.HasValue)
                throw NerfiesViews.Refuse("depth", noDepth?.Frame.ImagePath ?? "no hit",
                    "is needed for scene.json's near and far: this dataset has neither a depth map with a hit for every image nor the target's reach in dataset_config.json.",
                    "Capture with depth (depth: png in every split).");
            var distances = centres.Select(c => c.Length).ToList();
            result.Near = Math.Max(distances.Min() - reach.Value, 1e-3 * distances.Min());
            result.Far = distances.Max() + reach.Value;
            warnings.Add(new ValidationProblem("scene.json: near, far", ValidationProblem.Format(result.Near * result.Scale) + ", " + ValidationProblem.Format(result.Far * result.Scale),
                "bound the target's reach from the cameras (" + (noDepth != null ? noDepth.Frame.ImagePath + " has no depth map" : "no depth map has a hit") + "), not the exact nearest and farthest surface.",
                "Capture with depth for exact near and far (--to " + target + " reads the depth maps)."));
            return result;
        }

        /// <summary>The least and greatest pixel-centre ray distance to a hit over every view's depth map (output units); false when no pixel hits.</summary>
        static bool DepthRange(ExportScene scene, IReadOnlyList<NerfiesView> views, out double near, out double far)
        {
            near = double.PositiveInfinity;
            far = 0;
            var k = scene.Intrinsics;
            foreach (var v in views)
            {
                var steps = ReadDepthSteps(scene, v.Frame);
                for (var j = 0; j < k.Height; j++)
                {
                    var y = (j + 0.5 - k.Cy) / k.FlY;
                    for (var i = 0; i < k.Width; i++)
                    {
                        var step = steps[j * k.Width + i];
                        if (step == 0) continue;
                        var x = (i + 0.5 - k.Cx) / k.FlX;
                        var distance = step * scene.DepthUnitScale * Math.Sqrt(1 + x * x + y * y);
                        near = Math.Min(near, distance);
                        far = Math.Max(far, distance);
                    }
                }
            }
            return far > 0;
        }

        /// <summary>A frame's 16-bit depth steps (0 = no hit), checked to be the images' size.</summary>
        public static ushort[] ReadDepthSteps(ExportScene scene, ExportFrame frame)
        {
            // PngGray16Reader refuses, naming the file, anything but a 16-bit greyscale PNG.
            var steps = PngGray16Reader.Read(Path.Combine(scene.RootDirectory, frame.DepthPath), out var width, out var height);
            if (width != scene.Intrinsics.Width || height != scene.Intrinsics.Height)
                throw NerfiesViews.Refuse("depth", frame.DepthPath, "is " + width + " × " + height + ", not the images' " + scene.Intrinsics.Width + " × " + scene.Intrinsics.Height + ".",
                    "Re-capture the dataset's depth at the output size.");
            return steps;
        }
    }
}
