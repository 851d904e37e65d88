using System;
using System.Collections.Generic;
using System.Threading;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// One view's pixels, copied out of the GPU readback into managed arrays (so they outlive the frame and can go to
    /// a worker thread). All images have rows bottom-up (row 0 is the bottom of the picture), as Unity reads them back.
    /// The arrays are pooled: call <see cref="Release"/> once done with them, from any thread; touching them after that
    /// is a bug.
    /// </summary>
    public sealed class CapturedView
    {
        Action<CapturedView> _release;
        int _released;

        internal CapturedView(int viewIndex, UnityPose pose, int width, int height, int supersampling,
            int dataWidth, int dataHeight, Action<CapturedView> release)
        {
            ViewIndex = viewIndex;
            Pose = pose;
            Width = width;
            Height = height;
            Supersampling = supersampling;
            DataWidth = dataWidth;
            DataHeight = dataHeight;
            _release = release;
        }

        /// <summary>Index into the pose list the capture was given.</summary>
        public int ViewIndex { get; }

        /// <summary>The pose the camera had (the capturer's input, double precision), for writing its matrix.</summary>
        public UnityPose Pose { get; }

        /// <summary>Width of the colour renders and <see cref="Mask"/>: output width × <see cref="Supersampling"/>.</summary>
        public int Width { get; }

        /// <summary>Height of the colour renders and <see cref="Mask"/>: output height × <see cref="Supersampling"/>.</summary>
        public int Height { get; }

        public int Supersampling { get; }

        /// <summary>Width of <see cref="Depth"/> and <see cref="Normal"/>: the output width or the supersampled one.</summary>
        public int DataWidth { get; }

        public int DataHeight { get; }

        /// <summary>
        /// The colour pass rendered over a black clear: RGBA as IEEE half floats (R16G16B16A16_SFloat), 4 per pixel, the
        /// values the shaders wrote — linear light, or gamma-space when <see cref="ColorIsGammaEncoded"/>. The alpha
        /// channel is meaningless. With <see cref="ColorOverWhite"/> it gives alpha and straight colour
        /// (Core's DifferenceMatting). Null when the colour pass is off.
        /// </summary>
        public ushort[] ColorOverBlack { get; internal set; }

        /// <summary>The same view's colour pass over a white (1, 1, 1) clear; same layout as <see cref="ColorOverBlack"/>.</summary>
        public ushort[] ColorOverWhite { get; internal set; }

        /// <summary>
        /// Motion blur: the average of the view's sub-frame renders over black and over white (same layout as
        /// <see cref="ColorOverBlack"/>; pooled like it); <see cref="ColorOverBlack"/> is then the sharp render at the mid pose.
        /// Null without blur.
        /// </summary>
        public ushort[] BlurredOverBlack { get; internal set; }

        public ushort[] BlurredOverWhite { get; internal set; }

        /// <summary>True in a Gamma colour-space project: the colour values (and their blending) are in gamma space.</summary>
        public bool ColorIsGammaEncoded { get; internal set; }

        /// <summary>Coverage by the mask pass, 1 byte per pixel: 255 where the target's geometry covers the sample, 0 elsewhere.</summary>
        public byte[] Mask { get; internal set; }

        /// <summary>Eye depth (along the camera's forward axis) in Unity units, 1 float per pixel; 0 = no geometry.</summary>
        public float[] Depth { get; internal set; }

        /// <summary>
        /// 4 floats per pixel: the unit geometry normal in Unity's world frame (x, y, z) and 1 where geometry covers,
        /// all 0 elsewhere. The encoders relabel them into the dataset's world frame as they read them (<see cref="RawFrame.NormalsInUnityWorld"/>).
        /// </summary>
        public float[] Normal { get; internal set; }

        /// <summary>
        /// The labels pass at <see cref="Width"/> × <see cref="Height"/>, 4 bytes per sample: instance id (low byte, high
        /// byte), class id (low byte, high byte) of the renderer covering the sample, all 0 where none does. Null when the
        /// pass is off (<see cref="CapturePasses.Labels"/>).
        /// </summary>
        public byte[] Labels { get; internal set; }

        /// <summary>The material passes (issue 38) at <see cref="Width"/> × <see cref="Height"/>; null when off. Not pooled.</summary>
        public MaterialPassResult Materials { get; internal set; }

        /// <summary>
        /// Relighting (issue 38): the colour pair under each extra lighting render, by file key: [over black, over white],
        /// each laid out like <see cref="ColorOverBlack"/>. Null when off. Not pooled.
        /// </summary>
        public Dictionary<string, ushort[][]> Relit { get; internal set; }

        /// <summary>Gives the arrays back to the capture's pools. Safe to call more than once and from any thread.</summary>
        public void Release()
        {
            if (Interlocked.Exchange(ref _released, 1) != 0) return;
            var release = Interlocked.Exchange(ref _release, null);
            release?.Invoke(this);
            ColorOverBlack = null;
            ColorOverWhite = null;
            BlurredOverBlack = null;
            BlurredOverWhite = null;
            Mask = null;
            Depth = null;
            Normal = null;
            Labels = null;
            Materials = null;
            Relit = null;
        }
    }
}
