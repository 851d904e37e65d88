namespace NerfDatasetCreator
{
    /// <summary>
    /// Where a ray first meets a triangle mesh: the distance along the ray (in units of its direction's length), the
    /// triangle's index in the mesh's triangle list and the barycentric coordinates of the point,
    /// P = (1 − U − V)·A + U·B + V·C for the triangle's vertices A, B, C in the order the mesh lists them.
    /// </summary>
    public struct RayHit
    {
        public double T;
        public int Triangle;
        public double U;
        public double V;
    }
}
