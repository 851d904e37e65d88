namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// One material pass (issue 38). The numbers are the pass indices of <c>Shaders/NerfMaterial.shader</c>; URP renders
    /// the same quantity with the Rendering Debugger mode <see cref="IUrpMaterialDebugView"/> maps each one to.
    /// The shader's smoothness is rendered; the roughness written is 1 − smoothness (<see cref="MaterialShaderSupport.RoughnessFromSmoothness"/>).
    /// </summary>
    public enum MaterialPassKind
    {
        Albedo = 0,
        Metallic = 1,
        Smoothness = 2,
        Specular = 3,
        Emission = 4,
    }
}
