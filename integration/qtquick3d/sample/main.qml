// grass among Quick 3D's own models: a lawn of 12 m x 12 m (scene units are centimetres),
// a cube, a sphere, the ground under the grass, and a camera you move (W A S D, R F, mouse).
import QtQuick
import QtQuick3D
import QtQuick3D.Helpers
import Grass 1.0

Window {
    width: 960
    height: 540
    visible: true
    color: "#a9c6e8"
    title: "grass in Qt Quick 3D"

    View3D {
        id: view
        anchors.fill: parent
        renderMode: View3D.Inline // the window's pass and depth buffer: grass and models hide each other
        environment: SceneEnvironment { clearColor: "#a9c6e8"; backgroundMode: SceneEnvironment.Transparent }
        camera: camera

        PerspectiveCamera {
            id: camera
            position: Qt.vector3d(0, 160, 650)
            eulerRotation.x: -12
            clipNear: 5
            clipFar: 20000
        }
        DirectionalLight { eulerRotation: Qt.vector3d(-50, 20, 0); brightness: 1.2 }
        Model { // the ground under the grass
            source: "#Rectangle"
            scale: Qt.vector3d(14, 14, 1)
            eulerRotation.x: -90
            materials: PrincipledMaterial { baseColor: "#3b3114"; roughness: 1 }
        }
        Model {
            source: "#Cube"
            position: Qt.vector3d(-120, 50, 150)
            eulerRotation.y: 25
            materials: PrincipledMaterial { baseColor: "#c0392b"; roughness: 0.6 }
        }
        Model {
            source: "#Sphere"
            position: Qt.vector3d(170, 35, -80)
            scale: Qt.vector3d(1.4, 1.4, 1.4)
            materials: PrincipledMaterial { baseColor: "#e8e2d0"; roughness: 0.4 }
        }
    }
    GrassField {
        view: view
        extent: Qt.size(1200, 1200)
        cellSize: 25
    }
    WasdController { anchors.fill: parent; controlledObject: camera; speed: 2; shiftSpeed: 6 }
}
