// Geometry normals in Unity's world frame (unit length, signed), alpha 1 where geometry covers. The capturer
// converts them to the output world frame on the CPU (BlenderConvention.FromUnity). Normal maps are ignored.
// Rendered into a float RGBA target cleared to 0, so (0,0,0,0) means "no geometry".
Shader "Hidden/NerfDatasetCreator/Normal"
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
                float3 normal : NORMAL;
            };

            struct v2f
            {
                float4 pos : SV_POSITION;
                float3 worldNormal : TEXCOORD0;
            };

            v2f vert(appdata v)
            {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex.xyz);
                // Inverse-transpose of the object-to-world matrix: correct under non-uniform scale.
                o.worldNormal = UnityObjectToWorldNormal(v.normal);
                return o;
            }

            float4 frag(v2f i) : SV_Target
            {
                // Interpolation shortens the vector between vertices; renormalise per pixel.
                return float4(normalize(i.worldNormal), 1);
            }
            ENDCG
        }
    }
    Fallback Off
}
