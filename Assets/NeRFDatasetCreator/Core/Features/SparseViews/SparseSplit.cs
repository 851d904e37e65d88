using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One <c>splits/sparse_&lt;n&gt;.json</c>: which views of a dataset a sparse-view experiment trains on and which it
    /// scores, as indices into the frames of <c>transforms_train.json</c> and <c>transforms_test.json</c> (file order,
    /// from 0), with each frame's <c>file_path</c> beside them so a changed dataset is noticed, and the rule that chose them.
    /// </summary>
    public sealed class SparseSplit
    {
        public const string FolderName = "splits";
        public const string Prefix = "sparse_";

        public SparseSplit(int views, string rule, string source, IReadOnlyList<int> train, IReadOnlyList<string> trainFiles,
            IReadOnlyList<int> test, IReadOnlyList<string> testFiles)
        {
            Views = views;
            Rule = rule ?? throw new ArgumentNullException(nameof(rule));
            Source = source;
            Train = train ?? throw new ArgumentNullException(nameof(train));
            TrainFiles = trainFiles ?? throw new ArgumentNullException(nameof(trainFiles));
            Test = test ?? throw new ArgumentNullException(nameof(test));
            TestFiles = testFiles ?? throw new ArgumentNullException(nameof(testFiles));
        }

        /// <summary><c>sparse_&lt;n&gt;</c>: the name <c>evaluate --split</c> takes.</summary>
        public string Name => NameOf(Views);

        public int Views { get; }
        public string Rule { get; }

        /// <summary>The code that defines the lists (the papers' lists), or null (our farthest-point rule).</summary>
        public string Source { get; }

        public IReadOnlyList<int> Train { get; }
        public IReadOnlyList<string> TrainFiles { get; }
        public IReadOnlyList<int> Test { get; }
        public IReadOnlyList<string> TestFiles { get; }

        public static string NameOf(int views) => Prefix + views.ToString(System.Globalization.CultureInfo.InvariantCulture);

        /// <summary>The dataset-relative path of the file: <c>splits/sparse_&lt;n&gt;.json</c>.</summary>
        public static string RelativePath(string name) => FolderName + "/" + name + ".json";

        /// <summary>Whether <paramref name="fileName"/> is a split file's name, <c>sparse_&lt;n&gt;.json</c> (what OwnDataset accepts in splits/).</summary>
        public static bool IsFileName(string fileName) =>
            fileName.StartsWith(Prefix, StringComparison.Ordinal) && fileName.EndsWith(".json", StringComparison.Ordinal) &&
            fileName.Length > Prefix.Length + 5 && fileName.Substring(Prefix.Length, fileName.Length - Prefix.Length - 5).All(c => c >= '0' && c <= '9');

        public string ToJson()
        {
            var json = new JObject
            {
                ["name"] = Name,
                ["train_views"] = Views,
                ["rule"] = Rule,
            };
            if (Source != null) json["source"] = Source;
            json["indices_into"] = "the frames of transforms_train.json (train) and transforms_test.json (test), in file order, from 0";
            json["train"] = new JArray(Train.Select(i => (object)i).ToArray());
            json["test"] = new JArray(Test.Select(i => (object)i).ToArray());
            json["train_files"] = new JArray(TrainFiles.Select(f => (object)f).ToArray());
            json["test_files"] = new JArray(TestFiles.Select(f => (object)f).ToArray());
            return json.ToString(Formatting.Indented) + "\n";
        }

        /// <summary>Reads a split file; a malformed one is an <see cref="InvalidParameterException"/> naming the file and the key.</summary>
        public static SparseSplit Read(string path)
        {
            JObject json;
            try { json = JObject.Parse(FileOps.ReadText(path)); }
            catch (JsonException e) { throw Bad(path, "is not valid JSON (" + e.Message + ")."); }
            var train = Ints(json, "train", path);
            var test = Ints(json, "test", path);
            var trainFiles = Strings(json, "train_files", path, train.Count);
            var testFiles = Strings(json, "test_files", path, test.Count);
            var views = json["train_views"]?.Type == JTokenType.Integer ? (int)json["train_views"] : train.Count;
            return new SparseSplit(views, (string)json["rule"] ?? "", (string)json["source"], train, trainFiles, test, testFiles);
        }

        static List<int> Ints(JObject json, string key, string path)
        {
            if (!(json[key] is JArray array) || array.Any(t => t.Type != JTokenType.Integer || (long)t < 0 || (long)t > int.MaxValue))
                throw Bad(path, "has no \"" + key + "\" list of frame indices (whole numbers ≥ 0).");
            return array.Select(t => (int)t).ToList();
        }

        static List<string> Strings(JObject json, string key, string path, int count)
        {
            if (!(json[key] is JArray array) || array.Count != count || array.Any(t => t.Type != JTokenType.String))
                throw Bad(path, "has no \"" + key + "\" list of " + count + " file_path values, one per index.");
            return array.Select(t => (string)t).ToList();
        }

        static InvalidParameterException Bad(string path, string reason) =>
            new InvalidParameterException(new[] { new ValidationProblem("--split", path, reason, "Write it again with nerf-dataset splits <dataset> --views <n>.") });
    }
}
