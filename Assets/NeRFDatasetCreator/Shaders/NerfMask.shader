// Coverage mask: 1 wherever the target's geometry covers the pixel. The colour image's alpha comes from this pass,
// because lit shaders force opaque alpha to 1 and transparent ones blend it (see Documentation~/capture.md).
// One pass without a LightMode tag: the Built-in pipeline runs it as "Always", URP as "SRPDefaultUnlit".
Shader "Hidden/NerfDatasetCreator/Mask"
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
            };

            v2f vert(appdata v)
            {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex.xyz);
                return o;
            }

            float4 frag(v2f i) : SV_Target
            {
                return float4(1, 1, 1, 1);
            }
            ENDCG
        }
    }
    Fallback Off
}
