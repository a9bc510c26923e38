// SPDX-License-Identifier: Apache-2.0
// Skins through the binding: the mesh copied into managed and native arrays, its topology
// kept while the bowel moves, its metrics, a skin outliving its scene.
using System;
using System.Runtime.InteropServices;
using NUnit.Framework;

namespace Enteron.Tests
{
    [TestFixture]
    public unsafe class SkinTests
    {
        [Test]
        public void AConvolutionSkinIsAClosedTubeOfRadiusR()
        {
            using (Scene scene = Scene.FromJson(TestScenes.Minimal))
            using (var skin = new Skin(scene, SkinDesc.Default()))
            {
                Assert.AreEqual(0, skin.Mesh.VertexCount, "empty until the first update");
                for (int i = 0; i < 100; ++i) scene.Step(0.001);
                skin.Update();
                MeshInfo mesh = skin.Mesh;
                Assert.Greater(mesh.VertexCount, 100);
                Assert.Greater(mesh.TriangleCount, 100);
                Assert.AreEqual(0.1, mesh.TimeSeconds, 1e-12);
                Assert.AreEqual(1UL, mesh.Updates);
                Assert.IsTrue(mesh.TopologyChanged, "the first update makes the topology");
                Assert.IsTrue(mesh.StableTopology);

                var positions = new float[3 * mesh.VertexCount];
                var normals = new float[3 * mesh.VertexCount];
                var tangents = new float[3 * mesh.VertexCount];
                var u = new float[mesh.VertexCount];
                var v = new float[mesh.VertexCount];
                var indices = new int[3 * mesh.TriangleCount];
                skin.CopyPositions(positions);
                skin.CopyNormals(normals);
                skin.CopyTangents(tangents);
                skin.CopyAxisU(u);
                skin.CopyAroundV(v);
                skin.CopyIndices(indices);
                foreach (int index in indices) Assert.That(index, Is.InRange(0, mesh.VertexCount - 1));
                for (int i = 0; i < mesh.VertexCount; ++i)
                {
                    Assert.AreEqual(1.0, Length(normals, i), 1e-4, "unit normals");
                    Assert.AreEqual(1.0, Length(tangents, i), 1e-4, "unit tangents");
                    Assert.That(u[i], Is.InRange(0f, 1f));
                    Assert.That(v[i], Is.InRange(0f, 1f));
                    Assert.IsFalse(float.IsNaN(positions[3 * i]));
                }
                SkinMetrics metrics = skin.GetMetrics();
                Assert.AreEqual((uint)mesh.VertexCount, metrics.vertex_count);
                Assert.AreEqual(1, metrics.watertight, "a closed surface");
                Assert.Less(metrics.radius_error_rms, 0.02, "within 2 % of R");
                Assert.AreEqual(1.0, metrics.axis_length_m, 0.05, "the 1 m bowel");
            }
        }

        [Test]
        public void TheTopologyStaysWhileTheBowelMoves()
        {
            using (Scene scene = Scene.FromJson(TestScenes.Minimal))
            using (var skin = new Skin(scene, SkinDesc.Default(SkinMethod.Tube)))
            {
                skin.Update();
                MeshInfo first = skin.Mesh;
                var indices = new int[3 * first.TriangleCount];
                var firstPositions = new float[3 * first.VertexCount];
                skin.CopyIndices(indices);
                skin.CopyPositions(firstPositions);
                for (int frame = 0; frame < 10; ++frame)
                {
                    for (int i = 0; i < 20; ++i) scene.Step(0.001);
                    skin.Update();
                    MeshInfo mesh = skin.Mesh;
                    Assert.IsFalse(mesh.TopologyChanged, "frame " + frame);
                    Assert.AreEqual(first.TopologySerial, mesh.TopologySerial);
                    Assert.AreEqual(first.VertexCount, mesh.VertexCount);
                    var now = new int[indices.Length];
                    skin.CopyIndices(now);
                    CollectionAssert.AreEqual(indices, now, "the same indices");
                }
                var positions = new float[firstPositions.Length];
                skin.CopyPositions(positions);
                CollectionAssert.AreNotEqual(firstPositions, positions, "the vertices moved");
            }
        }

        [Test]
        public void NativeBuffersReceiveTheSameMesh()
        {
            using (Scene scene = Scene.FromJson(TestScenes.Minimal))
            using (var skin = new Skin(scene, SkinDesc.Default(SkinMethod.PointSkeleton)))
            {
                scene.Step(0.01);
                skin.Update();
                MeshInfo mesh = skin.Mesh;
                var positions = new float[3 * mesh.VertexCount];
                var indices = new int[3 * mesh.TriangleCount];
                skin.CopyPositions(positions);
                skin.CopyIndices(indices);
                IntPtr nativePositions = Marshal.AllocHGlobal(4 * positions.Length);
                IntPtr nativeIndices = Marshal.AllocHGlobal(4 * indices.Length);
                try
                {
                    skin.CopyPositions((float*)nativePositions, positions.Length);
                    skin.CopyIndices((uint*)nativeIndices, indices.Length);
                    var fromNative = new float[positions.Length];
                    var indicesFromNative = new int[indices.Length];
                    Marshal.Copy(nativePositions, fromNative, 0, fromNative.Length);
                    Marshal.Copy(nativeIndices, indicesFromNative, 0, indicesFromNative.Length);
                    CollectionAssert.AreEqual(positions, fromNative);
                    CollectionAssert.AreEqual(indices, indicesFromNative);
                    Assert.Throws<ArgumentException>(() => skin.CopyPositions((float*)nativePositions, positions.Length - 1),
                                                     "a capacity below the mesh");
                }
                finally
                {
                    Marshal.FreeHGlobal(nativePositions);
                    Marshal.FreeHGlobal(nativeIndices);
                }
                var error = Assert.Throws<ArgumentException>(() => skin.CopyPositions(new float[positions.Length - 1]));
                StringAssert.Contains("CopyPositions", error.Message);
            }
        }

        [Test]
        public void ASkinOutlivesItsScene()
        {
            Scene scene = Scene.FromJson(TestScenes.Minimal);
            using (var skin = new Skin(scene, SkinDesc.Default()))
            {
                for (int i = 0; i < 30; ++i) scene.Step(0.001);
                scene.Dispose();
                skin.Update();  // the last state the scene published
                MeshInfo mesh = skin.Mesh;
                Assert.AreEqual(0.03, mesh.TimeSeconds, 1e-12);
                Assert.Greater(mesh.VertexCount, 0);
                Assert.AreEqual(1, skin.GetMetrics().watertight);
                Assert.Throws<ObjectDisposedException>(() => new Skin(scene, SkinDesc.Default()), "no new skin of a disposed scene");
            }
        }

        [Test]
        public void ADisposedSkinRefusesEveryCall()
        {
            using (Scene scene = Scene.FromJson(TestScenes.Minimal))
            {
                var skin = new Skin(scene, SkinDesc.Default());
                skin.Update();
                skin.Dispose();
                skin.Dispose();
                Assert.IsTrue(skin.IsDisposed);
                Assert.Throws<ObjectDisposedException>(() => skin.Update());
                Assert.Throws<ObjectDisposedException>(() => skin.CopyPositions(new float[3]));
                Assert.Throws<ObjectDisposedException>(() => skin.GetMetrics());
            }
        }

        private static double Length(float[] xyz, int i)
        {
            return Math.Sqrt(xyz[3 * i] * xyz[3 * i] + xyz[3 * i + 1] * xyz[3 * i + 1] + xyz[3 * i + 2] * xyz[3 * i + 2]);
        }
    }
}
