using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Each case is a material as Unity's own inspector leaves it (properties and keywords from the shader sources
    /// cited in DataPassRules), and the data-pass settings read off those sources by hand.
    /// </summary>
    public class DataPassRulesTests
    {
        static MaterialSnapshot Standard(string mode) =>
            new MaterialSnapshot("Standard").WithFloat("_Cutoff", 0.3).WithColorAlpha("_Color", 0.8).WithTexture("_MainTex")
                .WithKeyword(mode);

        static MaterialSnapshot UrpLit(string shader, double cull, bool clip) =>
            new MaterialSnapshot(shader).WithFloat("_Cull", cull).WithFloat("_AlphaClip", clip ? 1 : 0).WithFloat("_Cutoff", 0.25)
                .WithColorAlpha("_BaseColor", 0.5).WithColorAlpha("_Color", 1).WithTexture("_BaseMap").WithTexture("_MainTex");

        [Test]
        public void AnEmptyMaterialSlotIsOpaqueFrontFacesOnly()
        {
            var s = DataPassRules.For(null);
            Assert.That(s.Cull, Is.EqualTo(FaceCulling.Back));
            Assert.That(s.AlphaClip, Is.False);
            Assert.That(s.IsExact, Is.True);
        }

        [Test]
        public void StandardCutoutClipsMainTexAlphaTimesColourAlphaAtItsCutoff()
        {
            var s = DataPassRules.For(Standard("_ALPHATEST_ON"));
            Assert.That(s.Cull, Is.EqualTo(FaceCulling.Back));
            Assert.That(s.AlphaClip, Is.True);
            Assert.That(s.Cutoff, Is.EqualTo(0.3));
            Assert.That(s.AlphaTexture, Is.EqualTo("_MainTex"));
            Assert.That(s.ColorAlpha, Is.EqualTo(0.8));
            Assert.That(s.IsExact, Is.True);
        }

        [TestCase("_ALPHABLEND_ON")]
        [TestCase("_ALPHAPREMULTIPLY_ON")]
        [TestCase("")]
        public void StandardOpaqueFadeAndTransparentDoNotClip(string mode)
        {
            var s = DataPassRules.For(Standard(mode));
            Assert.That(s.AlphaClip, Is.False);
            Assert.That(s.Cull, Is.EqualTo(FaceCulling.Back));
            Assert.That(s.IsExact, Is.True);
        }

        [Test]
        public void StandardWithSmoothnessInAlbedoAlphaClipsTheColourAlphaAlone()
        {
            var m = Standard("_ALPHATEST_ON").WithKeyword("_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A");
            var s = DataPassRules.For(m);
            Assert.That(s.AlphaClip, Is.True);
            Assert.That(s.AlphaTexture, Is.Null);
            Assert.That(s.ColorAlpha, Is.EqualTo(0.8));
        }

        [Test]
        public void StandardSpecularSetupFollowsTheSameRules()
        {
            var m = new MaterialSnapshot("Standard (Specular setup)").WithFloat("_Cutoff", 0.6).WithColorAlpha("_Color", 1)
                .WithTexture("_MainTex").WithKeyword("_ALPHATEST_ON");
            var s = DataPassRules.For(m);
            Assert.That(s.AlphaClip, Is.True);
            Assert.That(s.Cutoff, Is.EqualTo(0.6));
            Assert.That(s.AlphaTexture, Is.EqualTo("_MainTex"));
        }

        [TestCase("Unlit/Texture")]
        [TestCase("Unlit/Color")]
        [TestCase("Unlit/Transparent")]
        [TestCase("Legacy Shaders/Diffuse")]
        [TestCase("Legacy Shaders/Transparent/Diffuse")]
        [TestCase("Legacy Shaders/Self-Illumin/Bumped Specular")]
        public void BuiltInShadersWithoutCullOrClipAreExactlyOpaque(string shader)
        {
            var s = DataPassRules.For(new MaterialSnapshot(shader).WithTexture("_MainTex").WithColorAlpha("_Color", 0.2));
            Assert.That(s.Cull, Is.EqualTo(FaceCulling.Back));
            Assert.That(s.AlphaClip, Is.False);
            Assert.That(s.IsExact, Is.True, shader);
        }

        [Test]
        public void UnlitTransparentCutoutClipsTheTextureAlphaWithoutAColour()
        {
            var m = new MaterialSnapshot("Unlit/Transparent Cutout").WithFloat("_Cutoff", 0.5).WithTexture("_MainTex");
            var s = DataPassRules.For(m);
            Assert.That(s.AlphaClip, Is.True);
            Assert.That(s.Cutoff, Is.EqualTo(0.5));
            Assert.That(s.AlphaTexture, Is.EqualTo("_MainTex"));
            Assert.That(s.ColorAlpha, Is.EqualTo(1.0));
        }

        [TestCase("Legacy Shaders/Transparent/Cutout/Diffuse", FaceCulling.Back)]
        [TestCase("Legacy Shaders/Transparent/Cutout/Specular", FaceCulling.Back)]
        [TestCase("Legacy Shaders/Transparent/Cutout/Bumped Diffuse", FaceCulling.Back)]
        [TestCase("Legacy Shaders/Transparent/Cutout/VertexLit", FaceCulling.Back)]
        [TestCase("Legacy Shaders/Transparent/Cutout/Soft Edge Unlit", FaceCulling.Off)]
        public void LegacyCutoutShadersAlwaysClipMainTexTimesColour(string shader, FaceCulling cull)
        {
            var m = new MaterialSnapshot(shader).WithFloat("_Cutoff", 0.4).WithColorAlpha("_Color", 0.9).WithTexture("_MainTex");
            var s = DataPassRules.For(m);
            Assert.That(s.Cull, Is.EqualTo(cull));
            Assert.That(s.AlphaClip, Is.True, "no keyword needed: alphatest is compiled in");
            Assert.That(s.Cutoff, Is.EqualTo(0.4));
            Assert.That(s.AlphaTexture, Is.EqualTo("_MainTex"));
            Assert.That(s.ColorAlpha, Is.EqualTo(0.9));
        }

        [TestCase(0.0, FaceCulling.Off)]
        [TestCase(1.0, FaceCulling.Front)]
        [TestCase(2.0, FaceCulling.Back)]
        public void UrpLitTakesItsRenderFaceFromCull(double cull, FaceCulling expected)
        {
            Assert.That(DataPassRules.For(UrpLit("Universal Render Pipeline/Lit", cull, false)).Cull, Is.EqualTo(expected));
        }

        [TestCase("Universal Render Pipeline/Lit")]
        [TestCase("Universal Render Pipeline/Complex Lit")]
        [TestCase("Universal Render Pipeline/Simple Lit")]
        [TestCase("Universal Render Pipeline/Unlit")]
        [TestCase("Universal Render Pipeline/Baked Lit")]
        public void UrpShadersClipBaseMapAlphaTimesBaseColourAlphaUnderTheAlphaTestKeyword(string shader)
        {
            var s = DataPassRules.For(UrpLit(shader, 0, true).WithKeyword("_ALPHATEST_ON"));
            Assert.That(s.Cull, Is.EqualTo(FaceCulling.Off));
            Assert.That(s.AlphaClip, Is.True);
            Assert.That(s.Cutoff, Is.EqualTo(0.25));
            Assert.That(s.AlphaTexture, Is.EqualTo("_BaseMap"), "not the hidden _MainTex");
            Assert.That(s.ColorAlpha, Is.EqualTo(0.5), "_BaseColor, not the hidden _Color");
            Assert.That(s.IsExact, Is.True);
        }

        [Test]
        public void UrpFollowsTheKeywordTheShaderCompilesNotTheInspectorToggle()
        {
            // _AlphaClip = 1 without the keyword (a script set the float only): the shader does not clip, so neither do we.
            Assert.That(DataPassRules.For(UrpLit("Universal Render Pipeline/Lit", 2, true)).AlphaClip, Is.False);
        }

        [TestCase("_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A")]
        [TestCase("_GLOSSINESS_FROM_BASE_ALPHA")]
        public void UrpWithSmoothnessInTheBaseMapAlphaClipsTheColourAlphaAlone(string keyword)
        {
            var s = DataPassRules.For(UrpLit("Universal Render Pipeline/Simple Lit", 2, true).WithKeyword("_ALPHATEST_ON").WithKeyword(keyword));
            Assert.That(s.AlphaTexture, Is.Null);
            Assert.That(s.ColorAlpha, Is.EqualTo(0.5));
        }

        [TestCase(7.0)]
        [TestCase(-1.0)]
        public void AnOutOfRangeCullValueMeansUnitysDefaultBack(double cull)
        {
            Assert.That(DataPassRules.For(UrpLit("Universal Render Pipeline/Lit", cull, false)).Cull, Is.EqualTo(FaceCulling.Back));
        }

        [Test]
        public void AClippingMaterialWithoutACutoffUsesTheShadersDefaultHalf()
        {
            var m = new MaterialSnapshot("Universal Render Pipeline/Unlit").WithKeyword("_ALPHATEST_ON").WithTexture("_BaseMap");
            Assert.That(DataPassRules.For(m).Cutoff, Is.EqualTo(0.5));
        }

        [TestCase("_Cull", 0.0, FaceCulling.Off)]
        [TestCase("_BUILTIN_CullMode", 1.0, FaceCulling.Front)]
        public void AShaderGraphWithMaterialOverrideKeepsItsRenderFace(string property, double value, FaceCulling expected)
        {
            var s = DataPassRules.For(new MaterialSnapshot("Shader Graphs/Leaf", true).WithFloat(property, value));
            Assert.That(s.Cull, Is.EqualTo(expected));
            Assert.That(s.AlphaClip, Is.False);
            Assert.That(s.IsExact, Is.True);
        }

        [TestCase("_ALPHATEST_ON", null)]
        [TestCase(null, "_AlphaClip")]
        [TestCase("_BUILTIN_ALPHATEST_ON", null)]
        [TestCase(null, "_BUILTIN_AlphaClip")]
        public void AClippingShaderGraphWarnsThatItsAlphaCannotBeReproduced(string keyword, string toggle)
        {
            var m = new MaterialSnapshot("Shader Graphs/Leaf", true).WithFloat("_Cull", 0);
            if (keyword != null) m.WithKeyword(keyword);
            if (toggle != null) m.WithFloat(toggle, 1);
            var s = DataPassRules.For(m);
            Assert.That(s.AlphaClip, Is.False);
            Assert.That(s.Cull, Is.EqualTo(FaceCulling.Off));
            Assert.That(s.Warning, Does.Contain("Shader Graphs/Leaf").And.Contain("alpha"));
        }

        [Test]
        public void AShaderGraphWithoutMaterialOverrideIsOpaqueWithAWarningThatSaysHowToExposeIt()
        {
            var s = DataPassRules.For(new MaterialSnapshot("Shader Graphs/Rock", true).WithTexture("_BaseMap"));
            Assert.That(s.Cull, Is.EqualTo(FaceCulling.Back));
            Assert.That(s.AlphaClip, Is.False);
            Assert.That(s.Warning, Does.Contain("Shader Graphs/Rock").And.Contain("Allow Material Override"));
        }

        [TestCase("Custom/Foliage")]
        [TestCase("Legacy Shaders/Particles/Additive")]
        [TestCase("Nature/Tree Soft Occlusion Leaves")]
        public void AnUnknownShaderIsOpaqueWithAWarningNamingIt(string shader)
        {
            // Even with the usual property names: an unknown shader may use them for something else.
            var m = new MaterialSnapshot(shader).WithFloat("_Cull", 0).WithFloat("_Cutoff", 0.5).WithKeyword("_ALPHATEST_ON").WithTexture("_MainTex");
            var s = DataPassRules.For(m);
            Assert.That(s.Cull, Is.EqualTo(FaceCulling.Back));
            Assert.That(s.AlphaClip, Is.False);
            Assert.That(s.Warning, Does.Contain("'" + shader + "'"));
        }

        [Test]
        public void TheCullNumbersAreUnitysCullMode()
        {
            // UnityEngine.Rendering.CullMode: Off = 0, Front = 1, Back = 2 (UnityCsReference 2022.3 Runtime/Export/Graphics/GraphicsEnums.cs:1170-1175).
            Assert.That((int)FaceCulling.Off, Is.EqualTo(0));
            Assert.That((int)FaceCulling.Front, Is.EqualTo(1));
            Assert.That((int)FaceCulling.Back, Is.EqualTo(2));
        }
    }
}
