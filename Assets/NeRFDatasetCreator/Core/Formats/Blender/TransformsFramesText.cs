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
        ExposurePlan _exposure;

        TransformsFramesText(TextWriter output) => _output = output;

        /// <summary>
        /// Writes <c>,\n    "frames": [ … ]\n}</c> — the last member and the end of the file's object, whose earlier
        /// members Newtonsoft wrote — with the views of <paramref name="split"/> among <paramref name="views"/>.
        /// </summary>
        public static void Write(TextWriter output, System.Collections.Generic.IReadOnlyList<PlannedView> views, DatasetSplit? split, double rotation,
            ExposurePlan exposure = null)
        {
            var w = new TransformsFramesText(output) { _exposure = exposure };
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
            if (v.Time.HasValue)
            {
                var time = v.Time.Value;
                Key(TimeKeys.Time);
                Number(time.Normalised);
                Key(TimeKeys.Seconds);
                Number(time.Seconds);
                if (time.Camera >= 0)
                {
                    Key(TimeKeys.Step);
                    Integer(time.Step);
                    Key(TimeKeys.Camera);
                    Integer(time.Camera);
                }
            }
            if (_exposure != null && _exposure.Applies(v.Split))
            {
                var e = _exposure.For(v.Split, v.Index);
                Key(ExposureKeys.Ev);
                Number(e.Ev);
                Key(ExposureKeys.WhiteBalance);
                Raw("[\n                ");
                Number(e.R);
                Raw(",\n                ");
                Number(e.G);
                Raw(",\n                ");
                Number(e.B);
                Raw("\n            ]");
            }
            if (v.Motion != null) MotionKeys(v);
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
            if (v.Writes(DatasetFileKind.InstancePng))
            {
                Key(LabelFrameKeys.Instance);
                FilePath(v.Split, v.Index, DatasetFileKind.InstancePng);
            }
            if (v.Writes(DatasetFileKind.SemanticPng))
            {
                Key(LabelFrameKeys.Semantic);
                FilePath(v.Split, v.Index, DatasetFileKind.SemanticPng);
            }
            if (v.Writes(DatasetFileKind.CleanColor))
            {
                Key(ExposureKeys.CleanPath);
                FilePath(v.Split, v.Index, DatasetFileKind.CleanColor);
            }
            if (v.Writes(DatasetFileKind.SharpPng))
            {
                Key(MotionBlurKeys.SharpPath);
                FilePath(v.Split, v.Index, DatasetFileKind.SharpPng);
            }
            Raw("\n        }");
        }

        // instant-ngp's transform_matrix_start / _end (src/nerf_loader.cu reads them per frame), and the content times.
        void MotionKeys(PlannedView v)
        {
            var motion = v.Motion;
            MatrixKey(MotionBlurKeys.Start, motion.StartMatrix, v);
            MatrixKey(MotionBlurKeys.End, motion.EndMatrix, v);
            if (motion.OpenSeconds.HasValue && motion.CloseSeconds.HasValue)
            {
                Key(MotionBlurKeys.OpenSeconds);
                Number(motion.OpenSeconds.Value);
                Key(MotionBlurKeys.CloseSeconds);
                Number(motion.CloseSeconds.Value);
            }
        }

        void MatrixKey(string name, Matrix4x4d m, PlannedView v)
        {
            if (!m.IsFinite)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem(DatasetSplits.Name(v.Split) + "[" + v.Index + "]." + name, m.ToString(),
                        "is not finite; JSON cannot hold it.", "Check the motion blur settings that moved this camera."),
                });
            Key(name);
            Raw("[\n                [\n                    ");
            Rows(m);
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
