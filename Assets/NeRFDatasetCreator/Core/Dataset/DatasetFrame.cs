using System;
using System.Collections.Generic;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One entry of a transforms file's <c>frames</c>, as <see cref="DatasetFolder"/> reads it for every command: the pose
    /// as written, the time, per-frame intrinsics, every file its keys name (resolved from the key only, inside the
    /// dataset or refused: <see cref="DatasetFile"/>) and each feature's keys, read by that feature's own reader.
    /// </summary>
    public sealed class DatasetFrame
    {
        // Allocated on first use: validate streams 300 000-frame files, most of whose frames name no extra file.
        static readonly List<KeyValuePair<string, string>> NoFileKeys = new List<KeyValuePair<string, string>>();
        Dictionary<string, DatasetFile> _files;
        List<KeyValuePair<string, string>> _fileKeys = NoFileKeys;
        DatasetFile _image;
        List<string> _fileProblems;

        /// <summary>The transforms file the frame belongs to.</summary>
        public DatasetSplitFile File { get; internal set; }

        /// <summary>The split (<c>train</c>, <c>val</c>, <c>test</c>), or null for a file of another name.</summary>
        public string Split => File?.Split;

        /// <summary>The frame's position in <c>frames</c>.</summary>
        public int Index { get; internal set; }

        /// <summary>Whether the entry is a JSON object at all.</summary>
        public bool IsObject { get; internal set; }

        /// <summary>The entry as compact JSON text when it is not an object (for messages), else null.</summary>
        public string NotObjectText { get; internal set; }

        /// <summary><c>file_path</c> as written, or null when it is missing or not a string.</summary>
        public string FilePath { get; internal set; }

        public double? Rotation { get; internal set; }

        /// <summary><c>transform_matrix</c> when it had 4 rows of 4 numbers, as written (not checked further: NaN is kept), else null.</summary>
        public Matrix4x4d? TransformMatrix { get; internal set; }

        // The camera and feature keys are read on first use, by each feature's own reader: validate streams 300 000
        // frames and needs only the time keys of each.
        FrameIntrinsics _intrinsics;
        FrameShutter _shutter;
        FrameExposure _exposure;
        FrameMaterials _materials;
        FrameRelit _relit;
        IReadOnlyList<string> _distortionKeys;

        /// <summary>The frame's own camera keys (<c>fl_x</c>, <c>w</c>, …, which override the file's), <see cref="FrameIntrinsics.None"/> without.</summary>
        public FrameIntrinsics Intrinsics => _intrinsics ?? (_intrinsics = FrameIntrinsics.Read(Json));

        /// <summary>The time keys (<see cref="TimeKeys.Read"/>).</summary>
        public FrameTime Time { get; internal set; } = FrameTime.None;

        /// <summary>The motion-blur keys (<see cref="MotionBlurKeys.Read"/>; the rolling shutter falls back to the file's).</summary>
        public FrameShutter Shutter => _shutter ?? (_shutter = MotionBlurKeys.Read(File?.Top, Json));

        /// <summary>The exposure keys (<see cref="ExposureKeys.Read"/>).</summary>
        public FrameExposure Exposure => _exposure ?? (_exposure = ExposureKeys.Read(Json));

        /// <summary>The material files the frame names (<see cref="MaterialKeys.Read"/>).</summary>
        public FrameMaterials Materials => _materials ?? (_materials = MaterialKeys.Read(this));
        /// <summary>The relighting key <c>relit_paths</c> (<see cref="RelightingKeys.Read"/>).</summary>
        public FrameRelit Relit => _relit ?? (_relit = RelightingKeys.Read(Json));

        /// <summary>The relit image <c>relit_paths</c> names for <paramref name="key"/>, resolved inside the dataset or refused; null without it.</summary>
        public DatasetFile RelitFile(string key)
        {
            var written = Relit.PathOf(key);
            return written == null || File?.Root == null ? null : DatasetFile.Resolve(File.Root, RelightingKeys.RelitPaths + "." + key, written, false);
        }

        /// <summary>The lens coefficients (k1…p2) the frame or its file gives a non-zero number (<see cref="TransformsLens.NonZeroCoefficients"/>).</summary>
        public IReadOnlyList<string> DistortionKeys => _distortionKeys ?? (_distortionKeys = Json == null ? Array.Empty<string>() : TransformsLens.NonZeroCoefficients(File?.Top, Json));

        /// <summary>Problems with the frame's structure (Strict mode), e.g. "transform_matrix row 2 is not a list of 4 numbers.".</summary>
        public List<string> Problems { get; } = new List<string>();

        /// <summary>Every string-valued <c>*_path</c> key but <c>file_path</c> (depth_path, mask_path, sharp_path, …) as written, in the file's order.</summary>
        public IReadOnlyList<KeyValuePair<string, string>> FileKeys => _fileKeys;

        /// <summary>The frame as written: merge copies it verbatim.</summary>
        internal JObject Json { get; set; }

        /// <summary>A key's value as compact JSON text, or null when absent: for messages that quote what the frame holds.</summary>
        public string Text(string key) => Json?[key]?.ToString(Newtonsoft.Json.Formatting.None);

        /// <summary>The value of a file key as written, or null.</summary>
        public string FileKey(string key)
        {
            foreach (var pair in _fileKeys)
                if (pair.Key == key) return pair.Value;
            return null;
        }

        /// <summary>The colour image <c>file_path</c> names (".png" appended by the loaders' rule), or null without a string file_path or a folder.</summary>
        public DatasetFile Image
        {
            get
            {
                if (_image == null && FilePath != null && File?.Root != null) _image = DatasetFile.Resolve(File.Root, "file_path", FilePath, true);
                return _image;
            }
        }

        /// <summary>The file <paramref name="key"/> names (<c>depth_path</c>, …), resolved from the key only; null when the frame has no such key.</summary>
        public DatasetFile Named(string key)
        {
            if (key == "file_path") return Image;
            if (_files != null && _files.TryGetValue(key, out var file)) return file;
            var written = FileKey(key);
            if (written == null || File?.Root == null) return null;
            if (_files == null) _files = new Dictionary<string, DatasetFile>(StringComparer.Ordinal);
            return _files[key] = DatasetFile.Resolve(File.Root, key, written, false);
        }

        /// <summary>
        /// The file <paramref name="key"/> names when it is inside the dataset and exists, relative to it; else null —
        /// never a file guessed from the image's name (nerf_synthetic's own <c>r_0_depth_0000.png</c> are 8-bit pictures, not depth).
        /// </summary>
        public string Existing(string key)
        {
            var file = Named(key);
            return file != null && file.Exists ? file.Relative : null;
        }

        /// <summary>
        /// Strict mode: every file the frame names that leaves the dataset or is missing, naming the key and the file,
        /// in the file's key order (file_path first). Empty in lenient mode.
        /// </summary>
        public IReadOnlyList<string> FileProblems
        {
            get
            {
                if (_fileProblems != null) return _fileProblems;
                _fileProblems = new List<string>();
                if (File?.Mode != DatasetReadMode.Strict || File.Root == null) return _fileProblems;
                if (Image?.Problem is string image) _fileProblems.Add(image);
                foreach (var pair in _fileKeys)
                    if (Named(pair.Key)?.Problem is string problem) _fileProblems.Add(problem);
                return _fileProblems;
            }
        }

        internal void AddFileKey(string key, string value)
        {
            if (ReferenceEquals(_fileKeys, NoFileKeys)) _fileKeys = new List<KeyValuePair<string, string>>();
            _fileKeys.Add(new KeyValuePair<string, string>(key, value));
        }
    }
}
