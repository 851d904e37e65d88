using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>How a render's depth or normal file is stored.</summary>
    public enum RenderDataFormat
    {
        None,

        /// <summary>This plugin's encodings: depth 16-bit grey thousandths of an output unit, normals 8-bit RGB (n·0.5 + 0.5)·255.</summary>
        PluginPng,

        /// <summary>nerfstudio's raw outputs: gzip-compressed NumPy float arrays (H × W × 1 depth, H × W × 3 normals).</summary>
        NpyGz,
    }

    /// <summary>One frame of the split and the files a trainer rendered for it.</summary>
    public sealed class RenderView
    {
        public RenderView(int frameIndex, string framePath, string colourPath)
        {
            FrameIndex = frameIndex;
            FramePath = framePath;
            ColourPath = colourPath;
        }

        /// <summary>The frame's index in the split's transforms file.</summary>
        public int FrameIndex { get; }

        /// <summary>The frame's <c>file_path</c> as written (e.g. <c>./test/r_0</c>).</summary>
        public string FramePath { get; }

        public string ColourPath { get; }
        public string DepthPath { get; internal set; }
        public RenderDataFormat DepthFormat { get; internal set; }
        public string NormalPath { get; internal set; }
        public RenderDataFormat NormalFormat { get; internal set; }
    }

    /// <summary>What <see cref="RenderFolder.Read"/> found: the layout, the folder the files are in, one view per frame.</summary>
    public sealed class RenderSet
    {
        public RenderSet(RenderLayout layout, string folder, IReadOnlyList<RenderView> views, IReadOnlyList<string> notes)
        {
            Layout = layout;
            Folder = folder;
            Views = views;
            Notes = notes;
        }

        public RenderLayout Layout { get; }
        public string Folder { get; }
        public IReadOnlyList<RenderView> Views { get; }

        /// <summary>What the reader chose on the user's behalf (e.g. the latest of several 3DGS iterations).</summary>
        public IReadOnlyList<string> Notes { get; }
    }
}
