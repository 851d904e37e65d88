using System;
using System.Collections.Generic;
using System.IO;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The one reader of a dataset's transforms files — ours, nerf_synthetic's or any other tool's — for every command
    /// (validate, check, evaluate, convert, merge, imported poses, the time checks): splits → <see cref="DatasetSplitFile"/>s
    /// of <see cref="DatasetFrame"/>s, each with its pose as written, time, per-frame intrinsics, every file its keys
    /// name resolved from the key only by one path rule (<see cref="DatasetFile"/>: inside the dataset or refused), and
    /// each feature's keys read by that feature's reader (<see cref="TimeKeys.Read"/>, <see cref="MotionBlurKeys.Read"/>,
    /// <see cref="ExposureKeys.Read"/>, <see cref="TransformsLens.OfFile"/>). Malformed JSON throws
    /// <see cref="SettingsFormatException"/> with line and column; everything else that is odd is collected in the
    /// file's and frames' <c>Problems</c> in <see cref="DatasetReadMode.Strict"/> mode, so that a validator can list it all.
    /// </summary>
    public static class DatasetFolder
    {
        /// <summary>The per-frame file keys whose format validate checks (see Documentation~/output-format.md).</summary>
        public static readonly string[] CheckedFileKeys = { "depth_path", "depth_file_path", "normal_path", "mask_path", LabelFrameKeys.Instance, LabelFrameKeys.Semantic, MotionBlurKeys.SharpPath };

        /// <summary>The transforms file of <paramref name="split"/> in <paramref name="root"/>.</summary>
        public static string SplitPath(string root, string split) => Path.Combine(root, DatasetLayout.TransformsFileName(split));

        /// <summary>
        /// Reads <c>transforms_&lt;split&gt;.json</c> of the dataset folder <paramref name="root"/>, every frame kept. The
        /// file must exist (callers word a missing split their way); I/O errors and a file beyond
        /// <see cref="FileOps.MaxTextBytes"/> throw as <see cref="FileOps.ReadText"/> does.
        /// </summary>
        public static DatasetSplitFile ReadSplit(string root, string split, DatasetReadMode mode)
        {
            var path = SplitPath(root, split);
            return Read(FileOps.ReadText(path), Path.GetFileName(path), mode, Path.GetFullPath(root), split);
        }

        /// <summary>Reads a transforms file at any path (<paramref name="root"/> null: its frames' files are not resolved).</summary>
        public static DatasetSplitFile ReadFile(string path, DatasetReadMode mode, string root = null) =>
            Read(FileOps.ReadText(path), Path.GetFileName(path), mode, root == null ? null : Path.GetFullPath(root), SplitOfFileName(path));

        /// <summary>Reads transforms JSON text; <paramref name="root"/> (absolute) is where its frames' files resolve, null for none.</summary>
        public static DatasetSplitFile Read(string text, string sourceName = "transforms", DatasetReadMode mode = DatasetReadMode.Strict, string root = null, string split = null)
        {
            JToken token;
            try
            {
                // NaN and Infinity are not JSON, but Python's json module writes them; read them so they are reported as values.
                // Strings stay as written (no ISO dates turned into DateTime): merge writes frames back verbatim.
                using (var reader = new JsonTextReader(new StringReader(text ?? "")) { FloatParseHandling = FloatParseHandling.Double, DateParseHandling = DateParseHandling.None })
                {
                    token = JToken.ReadFrom(reader, new JsonLoadSettings { LineInfoHandling = LineInfoHandling.Ignore });
                    while (reader.Read())
                        if (reader.TokenType != JsonToken.Comment)
                            throw new JsonReaderException("Additional text after the JSON object.", reader.Path, reader.LineNumber, reader.LinePosition, null);
                }
            }
            catch (JsonReaderException e)
            {
                int line = e.LineNumber, column = e.LinePosition;
                var detail = JsonSyntaxHelp.Explain(e.Message, text, ref line, ref column,
                    "A transforms file is a JSON object with camera_angle_x and frames; write the split again (a capture, merge or convert).");
                throw new SettingsFormatException(sourceName, line, column, "", detail);
            }

            var doc = NewFile(sourceName, mode, root, split);
            if (!(token is JObject json))
            {
                doc.IsObject = false;
                doc.TypeShown = token.Type.ToString();
                doc.Problems.Add("is not a JSON object { … }.");
                return Finish(doc, null);
            }
            var top = new JObject();
            foreach (var property in json.Properties())
                if (property.Name != "frames") top[property.Name] = property.Value;
                else doc.FramesAt = top.Count;
            doc.Top = top;
            ReadTopLevel(top, doc);
            var frames = json["frames"];
            var lens = new TransformsLens.OfFile(sourceName);
            if (frames == null) doc.Problems.Add("has no \"frames\" list.");
            else if (!(frames is JArray list))
            {
                doc.Problems.Add("\"frames\" is not a list.");
                doc.FramesShown = frames.Type.ToString();
                doc.FramesText = frames.ToString(Formatting.None);
            }
            else
            {
                doc.HasFrameList = true;
                for (var i = 0; i < list.Count; i++)
                {
                    lens.Add(top, list[i] as JObject);
                    doc.Frames.Add(ReadFrame(doc, list[i], i));
                }
            }
            doc.FrameCount = doc.Frames.Count;
            return Finish(doc, lens);
        }

        static DatasetSplitFile NewFile(string sourceName, DatasetReadMode mode, string root, string split) =>
            new DatasetSplitFile { FileName = sourceName, Mode = mode, Root = root, Split = split };

        static DatasetSplitFile Finish(DatasetSplitFile doc, TransformsLens.OfFile lens)
        {
            if (lens != null)
            {
                doc.Lens = lens.Finish(doc.Top);
                doc.LensProblems.AddRange(lens.Problems);
            }
            if (doc.Mode == DatasetReadMode.Lenient) doc.Problems.Clear();
            return doc;
        }

        /// <summary>
        /// Reads a transforms file frame by frame, never holding more than one frame: <paramref name="onFrame"/> sees each
        /// and keeps what it needs. The file has every top-level value and <see cref="DatasetSplitFile.FrameCount"/>, but
        /// no <see cref="DatasetSplitFile.Frames"/> and no lens; a frame sees only the top-level keys written before
        /// <c>frames</c> (for the rolling-shutter and lens-coefficient fallbacks). A 300 000-view dataset's 87 MB files are
        /// read in constant memory. Malformed JSON throws <see cref="SettingsFormatException"/> — possibly after some frames
        /// were seen, so a caller that must not act on a broken file keeps its results until this returns.
        /// </summary>
        public static DatasetSplitFile ReadSplit(string datasetRoot, string split, DatasetReadMode mode, Action<DatasetFrame> onFrame)
        {
            var path = SplitPath(datasetRoot, split);
            var sourceName = Path.GetFileName(path);
            var fullRoot = Path.GetFullPath(datasetRoot);
            var doc = NewFile(sourceName, mode, fullRoot, split);
            var root = new JObject();
            doc.Top = root;
            var frameCount = 0;
            var framesSeen = false;
            var framesIsList = true;
            var noLineInfo = new JsonLoadSettings { LineInfoHandling = LineInfoHandling.Ignore };
            try
            {
                using (var text = FileOps.OpenText(path))
                using (var reader = new JsonTextReader(text) { FloatParseHandling = FloatParseHandling.Double, DateParseHandling = DateParseHandling.None })
                {
                    if (!ReadContent(reader) || reader.TokenType != JsonToken.StartObject)
                    {
                        // Not an object at all (or empty): rare and small; the whole-text reader words it as always.
                        text.Dispose();
                        return Read(FileOps.ReadText(path), sourceName, mode, fullRoot, split);
                    }
                    while (true)
                    {
                        if (!ReadContent(reader)) throw new JsonReaderException("Unexpected end of content while loading JObject.", reader.Path, reader.LineNumber, reader.LinePosition, null);
                        if (reader.TokenType == JsonToken.EndObject) break;
                        var name = (string)reader.Value;
                        if (!ReadContent(reader)) throw new JsonReaderException("Unexpected end of content while loading JObject.", reader.Path, reader.LineNumber, reader.LinePosition, null);
                        if (name == "frames") doc.FramesAt = root.Count;
                        if (name == "frames" && reader.TokenType == JsonToken.StartArray)
                        {
                            framesSeen = true;
                            framesIsList = true;
                            frameCount = 0;
                            while (true)
                            {
                                if (!ReadContent(reader)) throw new JsonReaderException("Unexpected end of content while loading JArray.", reader.Path, reader.LineNumber, reader.LinePosition, null);
                                if (reader.TokenType == JsonToken.EndArray) break;
                                var token = JToken.ReadFrom(reader, noLineInfo);
                                onFrame(ReadFrame(doc, token, frameCount));
                                frameCount++;
                            }
                        }
                        else
                        {
                            var value = JToken.ReadFrom(reader, noLineInfo);
                            if (name == "frames")
                            {
                                framesSeen = true;
                                framesIsList = false;
                                doc.FramesShown = value.Type.ToString();
                                doc.FramesText = value.ToString(Formatting.None);
                            }
                            else root[name] = value;
                        }
                    }
                    while (reader.Read())
                        if (reader.TokenType != JsonToken.Comment)
                            throw new JsonReaderException("Additional text after the JSON object.", reader.Path, reader.LineNumber, reader.LinePosition, null);
                }
            }
            catch (JsonReaderException e)
            {
                var cut = e.Message.IndexOf(" Path '", StringComparison.Ordinal);
                throw new SettingsFormatException(sourceName, e.LineNumber, e.LinePosition, "", "not valid JSON: " + (cut > 0 ? e.Message.Substring(0, cut) : e.Message));
            }
            ReadTopLevel(root, doc);
            if (!framesSeen) doc.Problems.Add("has no \"frames\" list.");
            else if (!framesIsList) doc.Problems.Add("\"frames\" is not a list.");
            doc.HasFrameList = framesSeen && framesIsList;
            doc.FrameCount = frameCount;
            return Finish(doc, null);
        }

        /// <summary>Reads the next token that is not a comment; false at the end of the text.</summary>
        static bool ReadContent(JsonReader reader)
        {
            while (reader.Read())
                if (reader.TokenType != JsonToken.Comment) return true;
            return false;
        }

        static void ReadTopLevel(JObject root, DatasetSplitFile doc)
        {
            doc.Intrinsics = FrameIntrinsics.Read(root);
            doc.CameraAngleX = Number(root, "camera_angle_x", doc.Problems, required: true);
            doc.CameraAngleY = Number(root, "camera_angle_y", doc.Problems, required: false);
            doc.W = Integer(root, "w", doc.Problems);
            doc.H = Integer(root, "h", doc.Problems);
            doc.IntegerDepthScale = Number(root, "integer_depth_scale", doc.Problems, required: false);
            doc.DepthUnitScaleFactor = Number(root, "depth_unit_scale_factor", doc.Problems, required: false);
            if (MotionBlurKeys.RollingShutterProblem(root[MotionBlurKeys.RollingShutter]) is string shutter) doc.Problems.Add(shutter);
        }

        static DatasetFrame ReadFrame(DatasetSplitFile doc, JToken token, int index)
        {
            var frame = new DatasetFrame { File = doc, Index = index };
            if (!(token is JObject obj))
            {
                frame.NotObjectText = token.ToString(Formatting.None);
                frame.Problems.Add("is not an object.");
                return Done(frame);
            }
            frame.IsObject = true;
            frame.Json = obj;
            var path = obj["file_path"];
            if (path == null) frame.Problems.Add("has no file_path.");
            else if (path.Type != JTokenType.String) frame.Problems.Add("file_path is not a string.");
            else frame.FilePath = (string)path;
            frame.Rotation = Number(obj, "rotation", frame.Problems, required: false);
            frame.TransformMatrix = Matrix(obj["transform_matrix"], frame.Problems);
            foreach (var key in CheckedFileKeys)
            {
                var value = obj[key];
                if (value != null && value.Type != JTokenType.String) frame.Problems.Add(key + " is not a string.");
            }
            // Every file key, in the file's order: this plugin's (depth_path, sharp_path, clean_path, instance_path …) and any other tool's *_path.
            foreach (var property in obj.Properties())
                if (property.Name != "file_path" && property.Name.EndsWith("_path", StringComparison.Ordinal) && property.Value.Type == JTokenType.String)
                    frame.AddFileKey(property.Name, (string)property.Value);
            // Each feature reads its own keys (Core/Features/<Feature>/…Keys.cs): the time keys here, the camera, shutter,
            // exposure and lens keys when first asked for (DatasetFrame).
            frame.Time = TimeKeys.Read(obj);
            if (MotionBlurKeys.RollingShutterProblem(obj[MotionBlurKeys.RollingShutter]) is string shutter) frame.Problems.Add(shutter);
            return Done(frame);
        }

        static DatasetFrame Done(DatasetFrame frame)
        {
            if (frame.File.Mode == DatasetReadMode.Lenient) frame.Problems.Clear();
            return frame;
        }

        /// <summary><c>transforms_test.json</c> → <c>test</c>; null for any other name.</summary>
        public static string SplitOfFileName(string path)
        {
            var file = Path.GetFileName(path ?? "");
            foreach (var split in DatasetSplits.Names)
                if (string.Equals(file, DatasetLayout.TransformsFileName(split), StringComparison.OrdinalIgnoreCase)) return split;
            return null;
        }

        static Matrix4x4d? Matrix(JToken token, List<string> problems)
        {
            if (token == null)
            {
                problems.Add("has no transform_matrix.");
                return null;
            }
            if (JsonMatrix.TryRead(token, "transform_matrix", out var matrix, out var problem)) return matrix;
            problems.Add(problem);
            return null;
        }

        static double? Number(JObject obj, string key, List<string> problems, bool required)
        {
            var token = obj[key];
            if (token == null)
            {
                if (required) problems.Add(key + " is missing.");
                return null;
            }
            if (TryNumber(token, out var value)) return value;
            problems.Add(key + " is not a number (" + token.ToString(Formatting.None) + ").");
            return null;
        }

        static int? Integer(JObject obj, string key, List<string> problems)
        {
            var token = obj[key];
            if (token == null) return null;
            if (TryNumber(token, out var value) && value == Math.Floor(value) && value >= int.MinValue && value <= int.MaxValue) return (int)value;
            problems.Add(key + " is not a whole number (" + token.ToString(Formatting.None) + ").");
            return null;
        }

        /// <summary>A JSON number of any size (<see cref="JsonValues"/>), or the NaN/Infinity tokens Python writes (reported later as not finite).</summary>
        static bool TryNumber(JToken token, out double value) => JsonValues.TryNumber(token, out value);
    }
}
