namespace NerfDatasetCreator
{
    /// <summary>The resolved geometry of a point or spot condition, in the output world.</summary>
    public static class LightGeometry
    {
        /// <summary>A spot's unit direction: as given, or from its position towards the origin (the target's centre in the output world) when not given.</summary>
        public static double[] SpotDirection(LightingCondition c)
        {
            Vector3d d = c.Direction != null ? new Vector3d(c.Direction[0], c.Direction[1], c.Direction[2]) : -new Vector3d(c.Position[0], c.Position[1], c.Position[2]);
            var n = d.Normalized();
            return new[] { n.X, n.Y, n.Z };
        }
    }
}
