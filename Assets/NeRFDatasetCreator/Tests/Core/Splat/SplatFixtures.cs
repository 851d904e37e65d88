using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Trained-model folders laid out as each trainer writes them, around one analytic scene: an asymmetric mesh in
    /// Unity's world (a tetrahedron and a tilted flag), a dataset of it (dataset_config.json with unity_frame,
    /// transforms_train.json with 8 cameras) and Gaussian centres sampled on the mesh, mapped into each trainer's frame
    /// exactly as that trainer's code maps its points (formulas and lines beside each builder).
    /// </summary>
    static class SplatFixtures
    {
        public static readonly Vector3d TargetCentreUnity = new Vector3d(0.4, 1.1, -0.6);
        public const double Scale = 2.5;

        public static SceneNormalisation Normalisation => new SceneNormalisation(BlenderConvention.FromUnity(TargetCentreUnity), Scale);

        /// <summary>The mesh in Unity's world: a tetrahedron and a flag, no symmetry a half turn could map onto itself.</summary>
        public static readonly Vector3d[] MeshUnity = new[]
        {
            new Vector3d(0, 0.8, -0.7), new Vector3d(1.2, 0.8, -0.7), new Vector3d(0, 1.6, -0.7), new Vector3d(0, 0.8, -0.2),
            new Vector3d(0.2, 2.2, -0.6), new Vector3d(0.9, 1.8, -1.0), new Vector3d(0.3, 1.7, -0.1),
        };

        public static readonly int[] Triangles = { 0, 1, 2, 0, 1, 3, 0, 2, 3, 1, 2, 3, 4, 5, 6 };

        /// <summary>The mesh's bounding-box diagonal in Unity units: "scene size" of the 1e-5 tolerance.</summary>
        public static double SceneSizeUnity => new Vector3d(MeshUnity.Max(v => v.X) - MeshUnity.Min(v => v.X), MeshUnity.Max(v => v.Y) - MeshUnity.Min(v => v.Y), MeshUnity.Max(v => v.Z) - MeshUnity.Min(v => v.Z)).Length;

        /// <summary>Points on the mesh (Unity world), area-weighted, from a fixed seed.</summary>
        public static List<Vector3d> SampleUnity(int count = 600, int seed = 1234)
        {
            var random = new Random(seed);
            var areas = new List<double>();
            for (var t = 0; t < Triangles.Length; t += 3)
                areas.Add(Vector3d.Cross(MeshUnity[Triangles[t + 1]] - MeshUnity[Triangles[t]], MeshUnity[Triangles[t + 2]] - MeshUnity[Triangles[t]]).Length / 2);
            var total = areas.Sum();
            var points = new List<Vector3d>();
            for (var i = 0; i < count; i++)
            {
                var pick = random.NextDouble() * total;
                var tri = 0;
                while (tri < areas.Count - 1 && pick > areas[tri]) { pick -= areas[tri]; tri++; }
                double r1 = Math.Sqrt(random.NextDouble()), r2 = random.NextDouble();
                Vector3d a = MeshUnity[Triangles[3 * tri]], b = MeshUnity[Triangles[3 * tri + 1]], c = MeshUnity[Triangles[3 * tri + 2]];
                points.Add(a * (1 - r1) + b * (r1 * (1 - r2)) + c * (r1 * r2));
            }
            return points;
        }

        /// <summary>The sampled points in the dataset's output frame: x_out = s·(B·x_unity − c), the plugin's forward map.</summary>
        public static List<Vector3d> SampleOutput() => SampleUnity().Select(Normalisation.ApplyToUnityPoint).ToList();

        /// <summary>8 train cameras (OpenGL camera-to-world, output frame) on a ring of radius 4 about the origin, +Z up.</summary>
        public static List<Matrix4x4d> TrainCameras()
        {
            var cameras = new List<Matrix4x4d>();
            for (var i = 0; i < 8; i++)
            {
                var azimuth = i * Math.PI / 4 + 0.1;
                var elevation = (i % 2 == 0 ? 20.0 : 35.0) * Math.PI / 180;
                var position = 4 * new Vector3d(Math.Cos(elevation) * Math.Cos(azimuth), Math.Cos(elevation) * Math.Sin(azimuth), Math.Sin(elevation));
                var back = position.Normalized();
                var right = Vector3d.Cross(Vector3d.UnitZ, back).Normalized();
                var up = Vector3d.Cross(back, right);
                cameras.Add(Matrix4x4d.FromColumns(right, up, back, position));
            }
            return cameras;
        }

        public const int Width = 40, Height = 30;
        public const double CameraAngleX = 0.8;

        /// <summary>A planned dataset: dataset_config.json (unity_frame, scene_normalisation; or only the latter) and transforms_train.json.</summary>
        public static string WriteDataset(string folder, bool withUnityFrame = true, UnityFrameFacts facts = null)
        {
            Directory.CreateDirectory(folder);
            var config = new JObject
            {
                ["generator"] = PluginInfo.Name,
                ["imagesRendered"] = false,
                [BlenderTransformsWriter.SceneNormalisationKey] = Normalisation.ToJson(),
            };
            if (withUnityFrame) config[UnityFrameRecord.Key] = UnityFrameRecord.ToJson(Normalisation, facts);
            File.WriteAllText(Path.Combine(folder, DatasetLayout.ConfigFileName), ExportJson.Serialise(config));
            var frames = new JArray(TrainCameras().Select((c, i) => new JObject { ["file_path"] = "./train/r_" + i, ["transform_matrix"] = ExportJson.Matrix(c) }));
            var train = new JObject { ["camera_angle_x"] = CameraAngleX, ["w"] = Width, ["h"] = Height, ["frames"] = frames };
            File.WriteAllText(Path.Combine(folder, "transforms_train.json"), ExportJson.Serialise(train));
            return folder;
        }

        // ---- Gaussian PLY, as 3DGS's GaussianModel.save_ply lays it out (binary little-endian floats) ----

        public static readonly string[] GaussianProperties =
        {
            "x", "y", "z", "nx", "ny", "nz", "f_dc_0", "f_dc_1", "f_dc_2", "opacity", "scale_0", "scale_1", "scale_2", "rot_0", "rot_1", "rot_2", "rot_3",
        };

        /// <summary>Writes the centres with opacity logit 2 (sigmoid 0.88) unless <paramref name="opacityLogits"/> says otherwise.</summary>
        public static void WriteGaussianPly(string path, IReadOnlyList<Vector3d> centres, IReadOnlyList<double> opacityLogits = null)
        {
            Directory.CreateDirectory(Path.GetDirectoryName(path));
            using (var stream = File.Create(path))
            using (var w = new BinaryWriter(stream))
            {
                var header = "ply\nformat binary_little_endian 1.0\nelement vertex " + centres.Count + "\n" + string.Concat(GaussianProperties.Select(p => "property float " + p + "\n")) + "end_header\n";
                w.Write(Encoding.ASCII.GetBytes(header));
                for (var i = 0; i < centres.Count; i++)
                {
                    w.Write((float)centres[i].X); w.Write((float)centres[i].Y); w.Write((float)centres[i].Z);
                    w.Write(0f); w.Write(0f); w.Write(0f);
                    w.Write(0.5f); w.Write(0.5f); w.Write(0.5f);
                    w.Write((float)(opacityLogits?[i] ?? 2.0));
                    w.Write(-4f); w.Write(-4f); w.Write(-4f);
                    w.Write(1f); w.Write(0f); w.Write(0f); w.Write(0f);
                }
            }
        }

        // ---- graphdeco 3DGS: model folder (train.py -m) ----

        /// <summary>
        /// cfg_args, cameras.json (Scene.__init__ writes one), point_cloud/iteration_{7000,30000,900}: 900 sorts last by
        /// name, 30000 is the highest by number and holds the centres; the others hold one far point each.
        /// </summary>
        public static string GaussianSplattingModel(string folder, IReadOnlyList<Vector3d> centres)
        {
            Directory.CreateDirectory(folder);
            File.WriteAllText(Path.Combine(folder, "cfg_args"), "Namespace(sh_degree=3, source_path='/data/lego', model_path='" + folder + "', images='images', resolution=-1, white_background=False, eval=True)");
            File.WriteAllText(Path.Combine(folder, "cameras.json"), "[]");
            WriteGaussianPly(Path.Combine(folder, "point_cloud", "iteration_30000", "point_cloud.ply"), centres);
            WriteGaussianPly(Path.Combine(folder, "point_cloud", "iteration_7000", "point_cloud.ply"), new[] { new Vector3d(100, 100, 100) });
            WriteGaussianPly(Path.Combine(folder, "point_cloud", "iteration_900", "point_cloud.ply"), new[] { new Vector3d(100, 100, 100) });
            return folder;
        }

        // ---- nerfstudio splatfacto: run folder outputs/<name>/splatfacto/<timestamp> ----

        /// <summary>A dataparser transform as auto_orient_and_center_poses returns one: a rotation and a translation (3×4).</summary>
        public static Matrix4x4d NerfstudioTransform => Matrix4x4d.FromColumns(
            Quaterniond.AngleAxis(37, new Vector3d(0.3, -0.5, 0.8)).Rotate(Vector3d.UnitX), Quaterniond.AngleAxis(37, new Vector3d(0.3, -0.5, 0.8)).Rotate(Vector3d.UnitY),
            Quaterniond.AngleAxis(37, new Vector3d(0.3, -0.5, 0.8)).Rotate(Vector3d.UnitZ), new Vector3d(0.12, -0.4, 0.25));

        public const double NerfstudioScale = 0.37;

        /// <summary>nerfstudio_dataparser.py lines 436–452: points @ transform_matrix.T, then *= scale_factor.</summary>
        public static Vector3d ToNerfstudio(Vector3d p) => NerfstudioTransform.MultiplyPoint(p) * NerfstudioScale;

        /// <summary>config.yml, dataparser_transforms.json (base_dataparser.py save_dataparser_transform), and, when <paramref name="exportFolder"/> is given, ns-export's splat.ply there.</summary>
        public static string NerfstudioRun(string folder, IReadOnlyList<Vector3d> centresInNerfstudio, string exportFolder, string method = "splatfacto")
        {
            Directory.CreateDirectory(folder);
            File.WriteAllText(Path.Combine(folder, "config.yml"), "!!python/object:nerfstudio.engine.trainer.TrainerConfig\n_target: !!python/name:nerfstudio.engine.trainer.Trainer ''\nexperiment_name: lego\nmethod_name: " + method + "\noutput_dir: !!python/object/apply:pathlib.PosixPath\n- outputs\n");
            var t = NerfstudioTransform;
            var json = new JObject
            {
                ["transform"] = new JArray(Enumerable.Range(0, 3).Select(r => new JArray(t[r, 0], t[r, 1], t[r, 2], t[r, 3]))),
                ["scale"] = NerfstudioScale,
            };
            File.WriteAllText(Path.Combine(folder, "dataparser_transforms.json"), json.ToString());
            if (exportFolder != null) WriteGaussianPly(Path.Combine(exportFolder, "splat.ply"), centresInNerfstudio);
            return folder;
        }

        // ---- gsplat simple_trainer: result folder with cfg.yml and ply/point_cloud_<step>.ply ----

        /// <summary>cfg.yml as yaml.dump(vars(cfg)) writes it (keys sorted, Python booleans), and ply/point_cloud_{6999,29999}.ply.</summary>
        public static string GsplatResult(string folder, IReadOnlyList<Vector3d> centres, string dataDir, bool normalise)
        {
            Directory.CreateDirectory(folder);
            File.WriteAllText(Path.Combine(folder, "cfg.yml"),
                "app_opt: false\nbatch_size: 1\ndata_dir: " + dataDir + "\ndata_factor: 1\nmax_steps: 30000\nnormalize_world_space: " + (normalise ? "true" : "false") +
                "\nply_steps:\n- 7000\n- 30000\nresult_dir: " + folder + "\nsave_ply: true\nstrategy: !!python/object:gsplat.strategy.default.DefaultStrategy\n  absgrad: false\ntest_every: 8\n");
            WriteGaussianPly(Path.Combine(folder, "ply", "point_cloud_29999.ply"), centres);
            WriteGaussianPly(Path.Combine(folder, "ply", "point_cloud_6999.ply"), new[] { new Vector3d(100, 100, 100) });
            return folder;
        }

        /// <summary>A COLMAP text model (sparse/0) of the train cameras and the sampled points, output frame, numbers round-trip exact.</summary>
        public static string WriteColmapText(string dataDir)
        {
            var sparse = Path.Combine(dataDir, "sparse", "0");
            Directory.CreateDirectory(sparse);
            string R(double v) => v.ToString("R", CultureInfo.InvariantCulture);
            File.WriteAllText(Path.Combine(sparse, "cameras.txt"), "1 PINHOLE " + Width + " " + Height + " 30 30 20 15\n");
            var images = new StringBuilder();
            var cameras = TrainCameras();
            for (var i = 0; i < cameras.Count; i++)
            {
                var pose = ColmapPose.FromCameraToWorld(cameras[i]);
                var q = pose.Rotation;
                images.Append((i + 1) + " " + R(q.W) + " " + R(q.X) + " " + R(q.Y) + " " + R(q.Z) + " " + R(pose.Translation.X) + " " + R(pose.Translation.Y) + " " + R(pose.Translation.Z) + " 1 r_" + i + ".png\n\n");
            }
            File.WriteAllText(Path.Combine(sparse, "images.txt"), images.ToString());
            var points = new StringBuilder();
            var sampled = SampleOutput();
            for (var i = 0; i < sampled.Count; i++)
                points.Append((i + 1) + " " + R(sampled[i].X) + " " + R(sampled[i].Y) + " " + R(sampled[i].Z) + " 128 128 128 0\n");
            File.WriteAllText(Path.Combine(sparse, "points3D.txt"), points.ToString());
            return dataDir;
        }
    }
}
