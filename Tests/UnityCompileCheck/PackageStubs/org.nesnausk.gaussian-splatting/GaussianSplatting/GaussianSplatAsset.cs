// Compile-check stub of aras-p/UnityGaussianSplatting v1.1.1 (9310dce438da726244ace17eaf6f768826435fa4),
// package/Runtime/GaussianSplatAsset.cs: the signatures the plugin uses, with no behaviour. Never shipped.
using System;
using UnityEngine;

namespace GaussianSplatting.Runtime // :9
{
    public class GaussianSplatAsset : ScriptableObject // :11
    {
        public enum VectorFormat { Float32, Norm16, Norm11, Norm6 } // :31-37
        public enum ColorFormat { Float32x4, Float16x4, Norm8x4, BC7 } // :51-57
        public enum SHFormat { Float32, Float16, Norm11, Norm6, Cluster64k, Cluster32k, Cluster16k, Cluster8k, Cluster4k } // :70-81

        // :103
        public void Initialize(int splats, VectorFormat formatPos, VectorFormat formatScale, ColorFormat formatColor, SHFormat formatSh, Vector3 bMin, Vector3 bMax, CameraInfo[] cameraInfos) =>
            throw new NotSupportedException("compile-check stub");

        public CameraInfo[] cameras => throw new NotSupportedException("compile-check stub"); // :229

        [Serializable]
        public struct CameraInfo // :239-245
        {
            public Vector3 pos;
            public Vector3 axisX, axisY, axisZ;
            public float fov;
        }
    }
}
