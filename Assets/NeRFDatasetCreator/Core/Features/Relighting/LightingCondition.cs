using System;

namespace NerfDatasetCreator
{
    /// <summary>What lights one relighting condition (issue 38).</summary>
    public enum LightingKind
    {
        /// <summary>An environment map (HDR cubemap or equirect texture) as the scene's only light, at one or more rotations.</summary>
        Environment,
        /// <summary>One point light, everything else off (one-light-at-a-time).</summary>
        Point,
        /// <summary>One spot light, everything else off.</summary>
        Spot,
    }

    /// <summary>
    /// One lighting condition of the "relighting" section: each (condition, rotation) is one more colour render per view;
    /// depth, normals, masks and material passes are shared with the scene's own lighting.
    /// </summary>
    [Serializable]
    public sealed class LightingCondition
    {
        /// <summary>The condition's name in file names and lights.json: lowercase letters, digits and '-' (e.g. "sunset", "olat-03").</summary>
        public string Name = "";

        public LightingKind Kind = LightingKind.Environment;

        /// <summary>Environment: the project path of the HDR texture (cubemap or equirect), e.g. "Assets/HDRI/sunset.exr".</summary>
        public string File = "";

        /// <summary>Environment: rotations in degrees, counter-clockwise about the output world's +Z seen from above (default one, 0).</summary>
        public double[] Rotations = { 0 };

        /// <summary>Environment: multiplier on the map; point / spot: the light's intensity in Unity's units.</summary>
        public double Intensity = 1;

        /// <summary>Point / spot: position in the OUTPUT world frame (Blender's, +Z up, output units).</summary>
        public double[] Position = { 0, 0, 4 };

        /// <summary>Spot: the direction it points, output world frame (default towards the origin).</summary>
        public double[] Direction;

        /// <summary>Spot: full cone angle in degrees.</summary>
        public double SpotAngle = 30;

        /// <summary>Point / spot: linear RGB colour.</summary>
        public double[] Colour = { 1, 1, 1 };

        /// <summary>Point / spot: cast shadows (on by default: the physically cleaner option).</summary>
        public bool Shadows = true;

        public LightingCondition Clone()
        {
            var copy = (LightingCondition)MemberwiseClone();
            copy.Rotations = (double[])Rotations?.Clone();
            copy.Position = (double[])Position?.Clone();
            copy.Direction = (double[])Direction?.Clone();
            copy.Colour = (double[])Colour?.Clone();
            return copy;
        }
    }
}
