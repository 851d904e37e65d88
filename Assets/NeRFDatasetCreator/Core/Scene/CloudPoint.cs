using System;

namespace NerfDatasetCreator
{
    /// <summary>One point of an initial cloud: position and unit normal (zero when unknown) in the output frame, and an 8-bit sRGB colour.</summary>
    public readonly struct CloudPoint
    {
        public CloudPoint(Vector3d position, Vector3d normal, byte red, byte green, byte blue)
        {
            Position = position;
            Normal = normal;
            Red = red;
            Green = green;
            Blue = blue;
        }

        public Vector3d Position { get; }
        public Vector3d Normal { get; }
        public byte Red { get; }
        public byte Green { get; }
        public byte Blue { get; }

        /// <summary>A colour channel in [0, 1] as a byte, rounded; values outside are clamped.</summary>
        public static byte ToByte(double channel)
        {
            if (double.IsNaN(channel)) return 0;
            return (byte)Math.Round(Math.Max(0, Math.Min(1, channel)) * 255, MidpointRounding.AwayFromZero);
        }

        /// <summary>
        /// This point sampled in Unity's world, moved into the normalised output world: positions through
        /// <paramref name="normalisation"/>, normals relabelled into Blender axes (a uniform scale keeps them unit).
        /// </summary>
        public CloudPoint FromUnityWorld(SceneNormalisation normalisation) => new CloudPoint(
            normalisation.ApplyToUnityPoint(Position), BlenderConvention.FromUnity(Normal), Red, Green, Blue);
    }
}
