using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The <c>frames</c> list of a transforms file, written by hand into a reused character buffer: character for
    /// character what Newtonsoft's indented writer (4 spaces) writes for it, with every number through
    /// <see cref="ShortestDoubleText"/>. A 300 000-view plan writes 4.8 million numbers here; through Newtonsoft and
    /// the runtime's "R" that was a string per number and most of the time of writing the files (12 s on Mono).
    /// Everything else in the file (a few keys) stays with Newtonsoft.
    /// </summary>
    sealed class TransformsFramesText
    {
        const int FlushAt = 1 << 14;
        readonly char[] _buffer = new char[FlushAt + 4096]; // room for one whole frame past the flush point
        readonly TextWriter _output;
        int _at;
        readonly ExposurePlan _exposure;

        TransformsFramesText(TextWriter output, DatasetSettings settings)
        {
            _output = output;
            _exposure = ExposurePlan.Of(settings); // drawn once per file, read per frame
        }

        /// <summary>
        /// Writes <c>,\n    "frames": [ … ]\n}</c> — the last member and the end of the file's object, whose earlier
        /// members Newtonsoft wrote — with the views of <paramref name="split"/> among <paramref name="views"/>.
        /// </summary>
        /// <param name="settings">Switch the optional outputs' per-frame keys on (null: none).</param>
        public static void Write(TextWriter output, System.Collections.Generic.IReadOnlyList<PlannedView> views, DatasetSplit? split, double rotation,
            DatasetSettings settings = null)
        {
            var w = new TransformsFramesText(output, settings);
            w.Raw(",\n    \"frames\": [");
            var any = false;
            for (var i = 0; i < views.Count; i++)
            {
                var v = views[i];
                if (split.HasValue && v.Split != split.Value) continue;
                w.Frame(v, rotation, any);
                any = true;
                if (w._at >= FlushAt) w.Flush();
            }
            w.Raw(any ? "\n    ]\n}" : "]\n}");
            w.Flush();
        }

        void Flush()
        {
            _output.Write(_buffer, 0, _at);
            _at = 0;
        }

        // The constant text between the values, joined into as few pieces as possible: each piece is one copy.
        const string Entry = ",\n            \"";
        const string MatrixStart = "\",\n            \"rotation\": ";
        const string FirstNumber = ",\n            \"transform_matrix\": [\n                [\n                    ";
        const string NextNumber = ",\n                    ";
        const string NextRow = "\n                ],\n                [\n                    ";
        const string MatrixEnd = "\n                ]\n            ]";
        static readonly string[] FirstFrame = SplitTexts("\n        {\n            \"file_path\": \"./", "/r_");
        static readonly string[] NextFrame = SplitTexts(",\n        {\n            \"file_path\": \"./", "/r_");
        static readonly string[] PathStart = SplitTexts("\"./", "/r_");

        static string[] SplitTexts(string before, string after)
        {
            var texts = new string[DatasetSplits.All.Count];
            foreach (var split in DatasetSplits.All) texts[(int)split] = before + DatasetSplits.Name(split) + after;
            return texts;
        }

        void Frame(PlannedView v, double rotation, bool comma)
        {
            var m = v.TransformMatrix;
            if (!m.IsFinite)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem(DatasetSplits.Name(v.Split) + "[" + v.Index + "].transform_matrix", m.ToString(), // Matrix4x4d formats with the invariant culture
                        "is not finite; JSON cannot hold it and every loader would fail.", "Check the settings that placed this camera."),
                });
            Raw((comma ? NextFrame : FirstFrame)[(int)v.Split]);
            Integer(v.Index);
            Raw(MatrixStart);
            Number(rotation);
            Raw(FirstNumber);
            Rows(m);
            // The optional outputs' keys (Core/Features/<Feature>/…Keys.cs), one line each, in the files' key order:
            // values after the pose, file paths after the core outputs' paths.
            TimeKeys.WriteFrame(this, v);
            ExposureKeys.WriteFrame(this, v, _exposure);
            MotionBlurKeys.WriteFrame(this, v);
            if (v.Writes(DatasetFileKind.DepthPng))
            {
                Key("depth_path");
                FilePath(v.Split, v.Index, DatasetFileKind.DepthPng);
                Key("depth_file_path");
                FilePath(v.Split, v.Index, DatasetFileKind.DepthPng);
            }
            if (v.Writes(DatasetFileKind.NormalPng))
            {
                Key("normal_path");
                FilePath(v.Split, v.Index, DatasetFileKind.NormalPng);
            }
            if (v.Writes(DatasetFileKind.MaskPng))
            {
                Key("mask_path");
                FilePath(v.Split, v.Index, DatasetFileKind.MaskPng);
            }
            LabelFrameKeys.WriteFrameFiles(this, v);
            ExposureKeys.WriteFrameFiles(this, v);
            HdrKeys.WriteFrameFiles(this, v);
            MaterialKeys.WriteFrameFiles(this, v);
            MotionBlurKeys.WriteFrameFiles(this, v);
            RelightingKeys.WriteFrameFiles(this, v);
            Raw("\n        }");
        }

        // The feature keys' writers (Core/Features/<Feature>/…Keys.cs) write through the members below.

        /// <summary><c>"key": "./split/r_i_suffix"</c> when <paramref name="v"/> writes a file of <paramref name="kind"/>.</summary>
        internal void FileKey(PlannedView v, DatasetFileKind kind, string key)
        {
            if (!v.Writes(kind)) return;
            Key(key);
            FilePath(v.Split, v.Index, kind);
        }

        /// <summary><c>"name": [[…], …]</c>, a 4×4 matrix as the rows <c>transform_matrix</c> is written in.</summary>
        internal void MatrixKey(string name, Matrix4x4d m)
        {
            Key(name);
            Raw("[\n                [\n                    ");
            Rows(m);
        }

        /// <summary><c>"name": [a, b, c]</c>, a list of three numbers on lines of their own, as Newtonsoft indents it.</summary>
        internal void TripleKey(string name, double a, double b, double c)
        {
            Key(name);
            Raw("[\n                ");
            Number(a);
            Raw(",\n                ");
            Number(b);
            Raw(",\n                ");
            Number(c);
            Raw("\n            ]");
        }

        /// <summary>
        /// <c>"name": { "key": "value", … }</c> as Newtonsoft indents it; keys and values are the plugin's own ASCII text
        /// (validated names and paths) without quotes, backslashes or control characters: nothing to escape.
        /// </summary>
        internal void StringObjectKey(string name, System.Collections.Generic.IReadOnlyList<string> keys, System.Collections.Generic.IReadOnlyList<string> values)
        {
            Key(name);
            if (keys.Count == 0)
            {
                Raw("{}");
                return;
            }
            Raw("{");
            for (var k = 0; k < keys.Count; k++)
            {
                if (_at >= FlushAt) Flush();
                Raw(k == 0 ? "\n                \"" : ",\n                \"");
                Raw(keys[k]);
                Raw("\": \"");
                Raw(values[k]);
                _buffer[_at++] = '"';
            }
            Raw("\n            }");
        }

        /// <summary><c>"name": value</c>.</summary>
        internal void NumberKey(string name, double value)
        {
            Key(name);
            Number(value);
        }

        /// <summary><c>"name": value</c> for a whole number.</summary>
        internal void IntegerKey(string name, int value)
        {
            Key(name);
            Integer(value);
        }

        // A matrix's four rows after its opening bracket, and the closing brackets.
        void Rows(Matrix4x4d m)
        {
            for (var r = 0; r < 4; r++)
            {
                if (r > 0) Raw(NextRow);
                Number(m[r, 0]);
                Raw(NextNumber);
                Number(m[r, 1]);
                Raw(NextNumber);
                Number(m[r, 2]);
                Raw(NextNumber);
                Number(m[r, 3]);
            }
            Raw(MatrixEnd);
        }

        // Keys and paths are the plugin's own ASCII text without quotes, backslashes or control characters: nothing to escape.
        void Key(string name)
        {
            Raw(Entry);
            Raw(name);
            Raw("\": ");
        }

        // DatasetLayout.FrameKeyPath ("./train/r_7_depth_0000.png") as a JSON string, built in place.
        void FilePath(DatasetSplit split, int index, DatasetFileKind kind)
        {
            Raw(PathStart[(int)split]);
            Integer(index);
            Raw(DatasetLayout.Suffix(kind));
            _buffer[_at++] = '"';
        }

        void Number(double value) => _at = ShortestDoubleText.WriteJson(value, _buffer, _at);

        void Integer(int value)
        {
            if (value < 0)
            {
                _buffer[_at++] = '-';
                if (value == int.MinValue)
                {
                    Raw("2147483648");
                    return;
                }
                value = -value;
            }
            var digits = 1;
            for (var rest = value / 10; rest > 0; rest /= 10) digits++;
            var end = _at + digits;
            for (var i = end - 1; i >= _at; i--)
            {
                _buffer[i] = (char)('0' + value % 10);
                value /= 10;
            }
            _at = end;
        }

        void Raw(string text)
        {
            text.CopyTo(0, _buffer, _at, text.Length);
            _at += text.Length;
        }
    }
}
