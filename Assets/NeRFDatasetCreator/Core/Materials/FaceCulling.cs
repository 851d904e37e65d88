namespace NerfDatasetCreator
{
    /// <summary>
    /// Which faces of a material the data passes draw. The numbers are UnityEngine.Rendering.CullMode's (Off 0,
    /// Front 1, Back 2): the data shader reads them as <c>Cull [_NerfCull]</c>, and URP's <c>_Cull</c> and Shader
    /// Graph's <c>_BUILTIN_CullMode</c> store the same numbers.
    /// </summary>
    public enum FaceCulling
    {
        /// <summary>Both faces (URP "Render Face: Both").</summary>
        Off = 0,
        /// <summary>Back faces only (URP "Render Face: Back").</summary>
        Front = 1,
        /// <summary>Front faces only: Unity's default.</summary>
        Back = 2,
    }
}
