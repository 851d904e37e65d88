using NUnit.Framework;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Review R4-8: <see cref="ContentClock"/> simulates particles at the content time exactly, not on the
    /// <c>Time.fixedDeltaTime</c> grid. One particle, burst at time 0, no shape (emitted at the origin along local +z),
    /// start speed 1, no gravity, local simulation space, lifetime 10 s: at content time t it is t units along z and t
    /// seconds old. Two times 5 ms apart (less than the default 20 ms fixed step) show it at two places; with
    /// <c>fixedTimeStep: true</c> both were the position at the last whole fixed step.
    /// </summary>
    [TestFixture]
    public class ParticleContentTimeTests
    {
        Scene _scene;

        [SetUp]
        public void SetUp() => _scene = TestScene.Open();

        [TearDown]
        public void TearDown() => TestScene.Close(_scene);

        static ParticleSystem OneParticle()
        {
            var go = new GameObject("One particle");
            var system = go.AddComponent<ParticleSystem>();
            system.Stop(true, ParticleSystemStopBehavior.StopEmittingAndClear);
            var main = system.main;
            main.duration = 5;
            main.loop = false;
            main.playOnAwake = false;
            main.startLifetime = 10;
            main.startSpeed = 1;
            main.startDelay = 0;
            main.gravityModifier = 0;
            main.simulationSpace = ParticleSystemSimulationSpace.Local;
            var emission = system.emission;
            emission.rateOverTime = 0;
            emission.rateOverDistance = 0;
            emission.SetBursts(new[] { new ParticleSystem.Burst(0f, 1) });
            var shape = system.shape;
            shape.enabled = false;
            return system;
        }

        static ParticleSystem.Particle Only(ParticleSystem system)
        {
            var particles = new ParticleSystem.Particle[4];
            Assert.That(system.GetParticles(particles), Is.EqualTo(1), "the burst's one particle");
            return particles[0];
        }

        [Test]
        public void TwoTimesFiveMillisecondsApartShowTheParticleAtTheirOwnTimes()
        {
            var system = OneParticle();
            var clock = new ContentClock(TimeSources.Particles, 7);
            foreach (var t in new[] { 0.505, 0.510, 0.513, 1.0 })
            {
                clock.Show(system.gameObject, t);
                var particle = Only(system);
                Assert.That(particle.position.z, Is.EqualTo((float)t).Within(1e-3f), "z = speed · t at " + t + " s");
                Assert.That(particle.startLifetime - particle.remainingLifetime, Is.EqualTo((float)t).Within(1e-3f), "age at " + t + " s");
            }
            clock.Show(system.gameObject, 0.505);
            var a = Only(system).position.z;
            clock.Show(system.gameObject, 0.510);
            Assert.That(Only(system).position.z - a, Is.EqualTo(0.005f).Within(1e-3f), "5 ms later, 5 mm further");
        }
    }
}
