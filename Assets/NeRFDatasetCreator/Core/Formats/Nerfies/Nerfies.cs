using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The files the Nerfies family shares (google/nerfies 1a38512, google/hypernerf d433ebe, KAIR-BAIR/dycheck ddf77a4,
    /// hustvl/4DGaussians 843d5ac): <c>dataset.json</c> with <c>ids</c>, <c>train_ids</c>, <c>val_ids</c>
    /// (nerfies/datasets/nerfies.py:66–78; 4DGaussians hyper_loader.py:59–77, which detects the layout by this file,
    /// scene/__init__.py:55–57) and <c>metadata.json</c> with each id's <c>warp_id</c>, <c>appearance_id</c>,
    /// <c>camera_id</c> (nerfies.py:179–193; hyper_loader.py:78–81; DyCheck datasets/nerfies.py:75–95).
    /// </summary>
    public static class Nerfies
    {
        public const string FolderName = "nerfies";
        public const string SceneFileName = "scene.json";
        public const string DatasetFileName = "dataset.json";
        public const string MetadataFileName = "metadata.json";
        public const string CameraFolder = "camera";
        public const string RgbFolder = "rgb";

        /// <summary>4DGaussians' initial cloud for this layout (dataset_readers.py:384–385, read with fetchPly: x, y, z, normals, red, green, blue).</summary>
        public const string PointCloudFileName = "points3D_downsample2.ply";

        /// <summary>The level 4DGaussians loads: <c>Load_hyper_data(datadir, 0.5, …)</c> → <c>rgb/{int(1/ratio)}x</c> = rgb/2x (dataset_readers.py:374–375, hyper_loader.py:96).</summary>
        public const int FourDGaussiansLevel = 2;

        /// <summary>The "&lt;k&gt;x" folder name of level <paramref name="factor"/>.</summary>
        public static string Level(int factor) => factor.ToString(System.Globalization.CultureInfo.InvariantCulture) + "x";

        /// <summary>dataset.json: the Nerfies capture notebook's keys (count, num_exemplars, ids, train_ids, val_ids); train first.</summary>
        public static JObject DatasetJson(IReadOnlyList<NerfiesView> views)
        {
            var train = views.Where(v => v.Train).Select(v => v.Id).ToList();
            var val = views.Where(v => !v.Train).Select(v => v.Id).ToList();
            return new JObject
            {
                ["count"] = views.Count,
                ["num_exemplars"] = train.Count,
                ["ids"] = new JArray(train.Concat(val).ToArray<object>()),
                ["train_ids"] = new JArray(train.ToArray<object>()),
                ["val_ids"] = new JArray(val.ToArray<object>()),
            };
        }

        /// <summary>metadata.json: per id, warp_id = appearance_id = the time id (as DyCheck's iPhone files, iphone.py:887–897), camera_id.</summary>
        public static JObject MetadataJson(IReadOnlyList<NerfiesView> views)
        {
            var metadata = new JObject();
            foreach (var v in views)
                metadata[v.Id] = new JObject { ["warp_id"] = v.TimeId, ["appearance_id"] = v.TimeId, ["camera_id"] = v.CameraId };
            return metadata;
        }
    }
}
