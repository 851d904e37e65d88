// Compile-check stub of aras-p/UnityGaussianSplatting v1.1.1 (9310dce438da726244ace17eaf6f768826435fa4),
// package/Runtime/GaussianSplatRenderer.cs: the signatures the plugin uses, with no behaviour. Never shipped.
using System;
using UnityEngine;

namespace GaussianSplatting.Runtime // :15
{
    public class GaussianSplatRenderer : MonoBehaviour // :215
    {
        public GaussianSplatAsset m_Asset; // :225
        public Shader m_ShaderSplats; // :246
        public Shader m_ShaderComposite; // :247
        public Shader m_ShaderDebugPoints; // :248
        public Shader m_ShaderDebugBoxes; // :249
        public ComputeShader m_CSSplatUtilities; // :251

        public GaussianSplatAsset asset => m_Asset; // :339

        public void ActivateCamera(int index) => throw new NotSupportedException("compile-check stub"); // :660
    }
}
