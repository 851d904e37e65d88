// The mask, depth and normal passes of a capture, drawn by DataPassRenderer with CommandBuffer.DrawRenderer outside
// any camera's render loop (no pipeline pass, prepass or renderer feature is involved; see
// Documentation~/capture.md, "The data passes"). Pass 0 = mask, 1 = depth, 2 = normal, 3 = labels (instance and
// class ids, Documentation~/maintainers/labels-capture.md).
//
// One material of this shader stands in for each source material, with the source's cull mode and alpha clipping
// copied in by the Editor from Core's DataPassRules: `Cull [_NerfCull]` (UnityEngine.Rendering.CullMode numbers),
// and, when _NerfClip is on, clip(tex.a × _NerfColorAlpha − _NerfCutoff) as Unity's shaders do. All three passes
// share the vertex code and the clip, so they cover exactly the same pixels.
Shader "Hidden/NerfDatasetCreator/Data"
{
    Properties
    {
        _NerfCull ("Cull", Float) = 2
        _NerfClip ("Alpha clip", Float) = 0
        _NerfCutoff ("Alpha cutoff", Float) = 0.5
        _NerfColorAlpha ("Colour alpha", Float) = 1
        _NerfAlphaTex ("Alpha texture", 2D) = "white" {}
    }

    CGINCLUDE
    #include "UnityCG.cginc"

    sampler2D _NerfAlphaTex;
    float4 _NerfAlphaTex_ST;
    float _NerfClip;
    float _NerfCutoff;
    float _NerfColorAlpha;
    // The ids of the renderer being drawn, set by DataPassRenderer with CommandBuffer.SetGlobalVector before its draws:
    // (instance low byte, instance high byte, class low byte, class high byte), each byte b as b / 255. Deliberately
    // not in the Properties block: "Global properties are used if a shader needs them but the material does not have
    // them defined (for example, if the shader does not expose them in Properties block)" (Scripting API
    // Shader.SetGlobalVector), so the one data material per source material serves every renderer that shares it.
    float4 _NerfLabelIds;

    struct appdata
    {
        float4 vertex : POSITION;
        float3 normal : NORMAL;
        float2 uv : TEXCOORD0;
    };

    struct v2f
    {
        float4 pos : SV_POSITION;
        float2 uv : TEXCOORD0;
        // View-space position: the camera at the origin looking along -z (unity_MatrixV, OpenGL convention).
        float3 viewPos : TEXCOORD1;
        float3 worldNormal : TEXCOORD2;
    };

    v2f vert(appdata v)
    {
        v2f o;
        o.pos = UnityObjectToClipPos(v.vertex.xyz);
        o.uv = TRANSFORM_TEX(v.uv, _NerfAlphaTex);
        o.viewPos = UnityObjectToViewPos(v.vertex.xyz);
        // Inverse-transpose of the object-to-world matrix: correct under non-uniform scale.
        o.worldNormal = UnityObjectToWorldNormal(v.normal);
        return o;
    }

    // The source material's alpha test: Unity's shaders discard where alpha < cutoff (clip(alpha - cutoff)).
    void ClipLikeTheSource(float2 uv)
    {
        float alpha = tex2D(_NerfAlphaTex, uv).a * _NerfColorAlpha;
        clip(_NerfClip > 0.5 ? alpha - _NerfCutoff : 1.0);
    }
    ENDCG

    SubShader
    {
        Tags { "RenderType" = "Opaque" "Queue" = "Geometry" }

        // Coverage: 1 wherever the target's geometry covers the pixel.
        Pass
        {
            Name "Mask"
            Cull [_NerfCull]
            ZWrite On
            ZTest LEqual
            Blend Off

            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 frag(v2f i) : SV_Target
            {
                ClipLikeTheSource(i.uv);
                return float4(1, 1, 1, 1);
            }
            ENDCG
        }

        // Eye depth: the distance along the camera's viewing axis, -z of the view-space position, in Unity units.
        // Taken from the interpolated view position rather than the z-buffer, so no _ZBufferParams, reversed-Z or
        // platform depth conventions are involved: view-space z is affine across a triangle, which perspective-correct
        // interpolation reproduces exactly. The R32_SFloat target is cleared to 0, so 0 means "no geometry".
        Pass
        {
            Name "Depth"
            Cull [_NerfCull]
            ZWrite On
            ZTest LEqual
            Blend Off

            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 frag(v2f i) : SV_Target
            {
                ClipLikeTheSource(i.uv);
                return float4(-i.viewPos.z, 0, 0, 1);
            }
            ENDCG
        }

        // Geometry normals in Unity's world frame (unit length), alpha 1 where geometry covers; normal maps are ignored.
        // A face seen from behind (two-sided materials) gets its normal turned towards the camera. Which side is
        // "behind" is decided geometrically, not with VFACE/SV_IsFrontFace: the triangle's plane normal comes from the
        // screen-space derivatives of the view position, is oriented towards the camera (at the view-space origin),
        // and the interpolated normal is flipped when it points to the other side of the surface. That holds whatever
        // the winding, the render-into-texture projection flip or the API, which VFACE's sign depends on.
        Pass
        {
            Name "Normal"
            Cull [_NerfCull]
            ZWrite On
            ZTest LEqual
            Blend Off

            CGPROGRAM
            #pragma target 3.0
            #pragma vertex vert
            #pragma fragment frag
            float4 frag(v2f i) : SV_Target
            {
                // Derivatives first: after a discard, neighbouring lanes' values are undefined on some APIs.
                float3 plane = cross(ddx(i.viewPos), ddy(i.viewPos));
                ClipLikeTheSource(i.uv);
                float3 worldNormal = normalize(i.worldNormal);
                // Towards the camera: the camera is at the view-space origin. (Edge-on, plane is 0 and nothing flips.)
                float3 towardsCamera = plane * sign(dot(plane, -i.viewPos));
                float3 viewNormal = mul((float3x3)UNITY_MATRIX_V, worldNormal);
                if (dot(viewNormal, towardsCamera) < 0) worldNormal = -worldNormal;
                return float4(worldNormal, 1);
            }
            ENDCG
        }

        // Labels: the drawn renderer's instance and class ids as exact integers in an R8G8B8A8_UNorm target (no sRGB,
        // no MSAA, no blending): R, G = instance id low and high byte, B, A = class id low and high byte; the clear
        // (0, 0, 0, 0) is id 0, the background. b / 255 written to an 8-bit UNORM channel is stored as b (float to
        // UNORM rounds to the nearest step), so the readback gives the bytes back exactly. The same vertex code, cull
        // mode, clip and depth test as the other passes, so the ids cover exactly the mask's samples.
        Pass
        {
            Name "Labels"
            Cull [_NerfCull]
            ZWrite On
            ZTest LEqual
            Blend Off

            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 frag(v2f i) : SV_Target
            {
                ClipLikeTheSource(i.uv);
                return _NerfLabelIds;
            }
            ENDCG
        }
    }
    Fallback Off
}
