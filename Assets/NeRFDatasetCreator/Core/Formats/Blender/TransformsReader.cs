using System;
using System.IO;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Reads Blender-format transforms files — ours, nerf_synthetic's or any other tool's. Malformed JSON throws
    /// <see cref="SettingsFormatException"/> with line and column; everything else that is odd is collected in the
    /// document's and frames' <c>Problems</c> so that a validator can list it all.
    /// </summary>
    public static class TransformsReader
    {
        /// <summary>The per-frame file keys this plugin writes and checks (see Documentation~/output-format.md).</summary>
        public static readonly string[] ExtraFileKeys = { "depth_path", "depth_file_path", "normal_path", "mask_path", LabelFrameKeys.Instance, LabelFrameKeys.Semantic };

        public static TransformsDocument ReadFile(string path) => Read(FileOps.ReadText(path), Path.GetFileName(path));

        public static TransformsDocument Read(string text, string sourceName = "transforms")
        {
            JToken token;
            try
            {
                // NaN and Infinity are not JSON, but Python's json module writes them; read them so they are reported as values.
                using (var reader = new JsonTextReader(new StringReader(text ?? "")) { FloatParseHandling = FloatParseHandling.Double })
                {
                    token = JToken.ReadFrom(reader, new JsonLoadSettings { LineInfoHandling = LineInfoHandling.Load });
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

            var doc = new TransformsDocument();
            if (!(token is JObject root))
            {
                doc.Problems.Add("is not a JSON object { … }.");
                return doc;
            }
            ReadTopLevel(root, doc);
            var frames = root["frames"];
            if (frames == null) doc.Problems.Add("has no \"frames\" list.");
            else if (!(frames is JArray list)) doc.Problems.Add("\"frames\" is not a list.");
            else
                for (var i = 0; i < list.Count; i++)
                    doc.Frames.Add(ReadFrame(list[i], i));
            doc.FrameCount = doc.Frames.Count;
            return doc;
        }

        /// <summary>
        /// Reads a transforms file frame by frame, never holding more than one frame: <paramref name="onFrame"/> sees each
        /// (as read, and its JSON object, null when it is not one) and keeps what it needs. The document has every
        /// top-level value and <see cref="TransformsDocument.FrameCount"/>, but no <see cref="TransformsDocument.Frames"/>.
        /// A 300 000-view dataset's 87 MB files are read in constant memory. Malformed JSON throws
        /// <see cref="SettingsFormatException"/> as <see cref="ReadFile(string)"/> does — possibly after some frames were
        /// seen, so a caller that must not act on a broken file keeps its results until this returns.
        /// </summary>
        public static TransformsDocument ReadFile(string path, Action<TransformsFrame, JObject> onFrame)
        {
            var sourceName = Path.GetFileName(path);
            var doc = new TransformsDocument();
            var root = new JObject();
            var frameCount = 0;
            var framesSeen = false;
            var framesIsList = true;
            var noLineInfo = new JsonLoadSettings { LineInfoHandling = LineInfoHandling.Ignore };
            try
            {
                using (var text = FileOps.OpenText(path))
                using (var reader = new JsonTextReader(text) { FloatParseHandling = FloatParseHandling.Double })
                {
                    if (!ReadContent(reader) || reader.TokenType != JsonToken.StartObject)
                    {
                        // Not an object at all (or empty): rare and small; the whole-text reader words it as always.
                        text.Dispose();
                        return Read(FileOps.ReadText(path), sourceName);
                    }
                    while (true)
                    {
                        if (!ReadContent(reader)) throw new JsonReaderException("Unexpected end of content while loading JObject.", reader.Path, reader.LineNumber, reader.LinePosition, null);
                        if (reader.TokenType == JsonToken.EndObject) break;
                        var name = (string)reader.Value;
                        if (!ReadContent(reader)) throw new JsonReaderException("Unexpected end of content while loading JObject.", reader.Path, reader.LineNumber, reader.LinePosition, null);
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
                                onFrame(ReadFrame(token, frameCount), token as JObject);
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
            doc.FrameCount = frameCount;
            return doc;
        }

        /// <summary>Reads the next token that is not a comment; false at the end of the text.</summary>
        static bool ReadContent(JsonReader reader)
        {
            while (reader.Read())
                if (reader.TokenType != JsonToken.Comment) return true;
            return false;
        }

        static void ReadTopLevel(JObject root, TransformsDocument doc)
        {
            doc.CameraAngleX = Number(root, "camera_angle_x", doc.Problems, required: true);
            doc.CameraAngleY = Number(root, "camera_angle_y", doc.Problems, required: false);
            doc.W = Integer(root, "w", doc.Problems);
            doc.H = Integer(root, "h", doc.Problems);
            doc.IntegerDepthScale = Number(root, "integer_depth_scale", doc.Problems, required: false);
            doc.DepthUnitScaleFactor = Number(root, "depth_unit_scale_factor", doc.Problems, required: false);
        }

        static TransformsFrame ReadFrame(JToken token, int index)
        {
            var frame = new TransformsFrame { Index = index };
            if (!(token is JObject obj))
            {
                frame.Problems.Add("is not an object.");
                return frame;
            }
            var path = obj["file_path"];
            if (path == null) frame.Problems.Add("has no file_path.");
            else if (path.Type != JTokenType.String) frame.Problems.Add("file_path is not a string.");
            else frame.FilePath = (string)path;
            frame.Rotation = Number(obj, "rotation", frame.Problems, required: false);
            frame.TransformMatrix = Matrix(obj["transform_matrix"], frame.Problems);
            foreach (var key in ExtraFileKeys)
            {
                var value = obj[key];
                if (value == null) continue;
                if (value.Type == JTokenType.String) frame.ExtraFiles[key] = (string)value;
                else frame.Problems.Add(key + " is not a string.");
            }
            return frame;
        }

        static Matrix4x4d? Matrix(JToken token, System.Collections.Generic.List<string> problems)
        {
            if (token == null)
            {
                problems.Add("has no transform_matrix.");
                return null;
            }
            if (!(token is JArray rows) || rows.Count != 4)
            {
                problems.Add("transform_matrix is not a list of 4 rows.");
                return null;
            }
            var m = new double[16];
            for (var r = 0; r < 4; r++)
            {
                if (!(rows[r] is JArray row) || row.Count != 4)
                {
                    problems.Add("transform_matrix row " + r + " is not a list of 4 numbers.");
                    return null;
                }
                for (var c = 0; c < 4; c++)
                {
                    if (!TryNumber(row[c], out var v))
                    {
                        problems.Add("transform_matrix[" + r + "][" + c + "] is not a number (" + row[c].ToString(Formatting.None) + ").");
                        return null;
                    }
                    m[r * 4 + c] = v;
                }
            }
            return Matrix4x4d.FromRowMajor(m);
        }

        static double? Number(JObject obj, string key, System.Collections.Generic.List<string> problems, bool required)
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

        static int? Integer(JObject obj, string key, System.Collections.Generic.List<string> problems)
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
