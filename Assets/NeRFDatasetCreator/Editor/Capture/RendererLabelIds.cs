using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The instance and class id one renderer is drawn with in the labels pass (<see cref="CapturePasses.Labels"/>), and
    /// their encoding as the colour the shader writes: each id as its low and high byte, each byte b as b / 255, which an
    /// 8-bit UNORM target stores as b exactly (Documentation~/maintainers/labels-capture.md).
    /// </summary>
    public readonly struct RendererLabelIds
    {
        public RendererLabelIds(int instance, int classId)
        {
            Instance = (ushort)instance;
            Class = (ushort)classId;
        }

        /// <summary>1–65535; 0 is the background.</summary>
        public ushort Instance { get; }

        /// <summary>0 (no class) to 65535.</summary>
        public ushort Class { get; }

        /// <summary>(instance low, instance high, class low, class high), each byte / 255: the shader's <c>_NerfLabelIds</c>.</summary>
        public Vector4 Encoded => new Vector4((Instance & 0xFF) / 255f, (Instance >> 8) / 255f, (Class & 0xFF) / 255f, (Class >> 8) / 255f);

        /// <summary>The instance id of sample <paramref name="sample"/> of a labels readback (4 bytes per sample).</summary>
        public static int InstanceAt(byte[] labels, int sample) => labels[sample * 4] | (labels[sample * 4 + 1] << 8);

        /// <summary>The class id of sample <paramref name="sample"/> of a labels readback.</summary>
        public static int ClassAt(byte[] labels, int sample) => labels[sample * 4 + 2] | (labels[sample * 4 + 3] << 8);
    }
}
