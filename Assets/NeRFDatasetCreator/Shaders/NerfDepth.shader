// Eye depth: the distance along the camera's viewing axis, -z of the view-space position, in Unity units (metres).
// Taken from the interpolated view position rather than the z-buffer, so no _ZBufferParams, reversed-Z or
// platform depth conventions are involved. View-space z is linear across a triangle, and the rasteriser's
// perspective-correct interpolation reproduces such an attribute exactly at every pixel.
// Rendered into an R32_SFloat target cleared to 0, so 0 means "no geometry".
Shader "Hidden/NerfDatasetCreator/Depth"
{
    SubShader
    {
        Tags { "RenderType" = "Opaque" "Queue" = "Geometry" }
        Pass
        {
            Cull Back
            ZWrite On
            ZTest LEqual
            Blend Off

            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"

            struct appdata
            {
                float4 vertex : POSITION;
            };

            struct v2f
            {
                float4 pos : SV_POSITION;
                float eyeDepth : TEXCOORD0;
            };

            v2f vert(appdata v)
            {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex.xyz);
                o.eyeDepth = -UnityObjectToViewPos(v.vertex.xyz).z;
                return o;
            }

            float4 frag(v2f i) : SV_Target
            {
                return float4(i.eyeDepth, 0, 0, 1);
            }
            ENDCG
        }
    }
    Fallback Off
}
