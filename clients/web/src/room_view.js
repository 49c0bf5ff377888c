// The 3D view: the solved patch mesh, Gouraud-shaded by the streamed per-vertex radiosity (as
// grey luminance, or dimmed under the false-colour sensors), the sensor sets as false-colour
// tiles (grids) and markers (points), and an orbit camera. Renders on demand, not every frame.
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import {
    falseColour,
    grey,
    luminanceFromRadiosity,
    luminanceTop,
    niceCeiling,
} from "./colour_scale.js";

const BACKGROUND = 0x1d2229;
/// In false-colour mode the room is drawn this much darker, so the sensors stand out.
const ROOM_DIMMING = 0.55;

export class RoomView {
    constructor(container) {
        this.container = container;
        this.renderer = new THREE.WebGLRenderer({ antialias: true });
        this.renderer.setPixelRatio(window.devicePixelRatio);
        this.renderer.domElement.id = "room";
        container.appendChild(this.renderer.domElement);
        this.scene = new THREE.Scene();
        this.scene.background = new THREE.Color(BACKGROUND);
        this.camera = new THREE.PerspectiveCamera(45, 1, 0.01, 1000);
        this.camera.up.set(0, 0, 1); // scenes are z-up
        this.controls = new OrbitControls(this.camera, this.renderer.domElement);
        this.controls.addEventListener("change", () => this.render());
        this.room = null;
        this.sensors = new THREE.Group();
        this.scene.add(this.sensors);
        this.mode = "luminance";
        this.radiosity = null;
        this.sensorData = { layouts: [], illuminance: [] };
        new ResizeObserver(() => this.resize()).observe(container);
        this.resize();
    }

    resize() {
        const { clientWidth: w, clientHeight: h } = this.container;
        if (!w || !h) return;
        this.renderer.setSize(w, h);
        this.camera.aspect = w / h;
        this.camera.updateProjectionMatrix();
        this.render();
    }

    render() {
        this.renderer.render(this.scene, this.camera);
    }

    /// Forgets the room (another job is opened).
    clear() {
        if (this.room) {
            this.scene.remove(this.room);
            this.room.geometry.dispose();
            this.room.material.dispose();
        }
        this.room = null;
        this.radiosity = null;
        this.meshVersion = null;
        this.setSensors([], []);
        this.framed = false;
        this.render();
    }

    /// A new patch mesh (events.js decodeMesh); its colours come with the next radiosity.
    setMesh(mesh) {
        const geometry = new THREE.BufferGeometry();
        geometry.setAttribute("position", new THREE.BufferAttribute(mesh.positions, 3));
        geometry.setIndex(new THREE.BufferAttribute(mesh.indices, 1));
        geometry.setAttribute(
            "color",
            new THREE.BufferAttribute(new Float32Array(mesh.positions.length).fill(0.15), 3),
        );
        geometry.computeBoundingBox();
        geometry.computeBoundingSphere();
        if (this.room) {
            this.scene.remove(this.room);
            this.room.geometry.dispose();
            this.room.material.dispose();
        }
        // Back faces are not drawn: from outside, a room's near walls and ceiling do not hide it.
        this.room = new THREE.Mesh(
            geometry,
            new THREE.MeshBasicMaterial({ vertexColors: true, side: THREE.FrontSide }),
        );
        this.scene.add(this.room);
        this.meshVersion = mesh.meshVersion;
        this.radiosity = null;
        if (!this.framed) this.frame();
        this.render();
    }

    /// Per-vertex radiosity (lm/m²) of the current mesh; false when it does not fit that mesh.
    setRadiosity(radiosity) {
        if (!this.room || radiosity.meshVersion !== this.meshVersion) return false;
        if (radiosity.vertexRadiosity.length !== this.room.geometry.attributes.position.count)
            return false;
        this.radiosity = radiosity.vertexRadiosity;
        this.recolour();
        return true;
    }

    /// Sensor sets (sensor_geometry.js layouts) and their illuminance (lux), in the same order.
    setSensors(layouts, illuminance) {
        this.sensorData = { layouts, illuminance };
        this.recolour();
    }

    setMode(mode) {
        this.mode = mode;
        this.recolour();
    }

    /// The legend of what is shown: {kind: "luminance" | "illuminance", top} (top in cd/m² or lux).
    legend() {
        if (this.mode === "lux") return { kind: "illuminance", top: this.luxTop() };
        return { kind: "luminance", top: this.radiosity ? luminanceTop(this.radiosity) : 1 };
    }

    luxTop() {
        const all = this.sensorData.illuminance.flat().filter(Number.isFinite);
        return niceCeiling(all.length ? Math.max(...all) : 0);
    }

    recolour() {
        if (this.room && this.radiosity) {
            const top = luminanceTop(this.radiosity);
            const dim = this.mode === "lux" ? ROOM_DIMMING : 1;
            const colours = this.room.geometry.attributes.color;
            this.radiosity.forEach((b, i) => {
                const [r, g, bl] = grey((dim * luminanceFromRadiosity(b)) / top);
                colours.setXYZ(i, r, g, bl);
            });
            colours.needsUpdate = true;
        }
        this.buildSensors();
        this.render();
    }

    buildSensors() {
        for (const child of [...this.sensors.children]) {
            this.sensors.remove(child);
            child.geometry.dispose();
            child.material.dispose();
        }
        const { layouts, illuminance } = this.sensorData;
        const top = this.luxTop();
        const lux = this.mode === "lux";
        const colourOf = (set, i) =>
            lux ? falseColour((illuminance[set]?.[i] ?? NaN) / top) : [1, 1, 1];
        const tiles = [];
        const tileColours = [];
        const markers = [];
        layouts.forEach((layout, set) => {
            layout.points.forEach((p, i) => {
                const colour = colourOf(set, i);
                if (layout.cell && lux) {
                    tiles.push(tileCorners(p, layout.cell, layout.normal));
                    tileColours.push(colour);
                } else {
                    markers.push({ p, colour });
                }
            });
        });
        if (tiles.length) this.sensors.add(tileMesh(tiles, tileColours));
        if (markers.length) this.sensors.add(markerMesh(markers, this.markerRadius()));
    }

    markerRadius() {
        const radius = this.room?.geometry.boundingSphere?.radius ?? 2;
        return Math.min(0.05, Math.max(0.01, radius * 0.008));
    }

    /// Looks at the room from the front, to the left and above, all of it in view.
    frame() {
        if (!this.room) return;
        const box = this.room.geometry.boundingBox;
        const centre = box.getCenter(new THREE.Vector3());
        const radius = Math.max(this.room.geometry.boundingSphere.radius, 0.1);
        const fit =
            radius /
            Math.sin(THREE.MathUtils.degToRad(this.camera.fov / 2)) /
            Math.min(1, this.camera.aspect);
        const direction = new THREE.Vector3(-0.45, -1, 1.1).normalize();
        this.camera.position.copy(centre).addScaledVector(direction, fit * 0.95);
        this.camera.near = fit / 100;
        this.camera.far = fit * 10;
        this.camera.updateProjectionMatrix();
        this.controls.target.copy(centre);
        this.controls.update();
        this.framed = true;
    }

    /// Where the scene point p (metres) appears on the canvas, in CSS pixels from its top left.
    project(p) {
        const v = new THREE.Vector3(...p).project(this.camera);
        const { clientWidth: w, clientHeight: h } = this.renderer.domElement;
        return { x: ((v.x + 1) / 2) * w, y: ((1 - v.y) / 2) * h };
    }
}

/// A sensor cell's four corners around its centre p, lifted 1 cm along its normal.
function tileCorners(p, cell, normal) {
    const n = new THREE.Vector3(...normal).normalize().multiplyScalar(0.01);
    const c = new THREE.Vector3(...p).add(n);
    const u = new THREE.Vector3(...cell.u).multiplyScalar(0.5);
    const v = new THREE.Vector3(...cell.v).multiplyScalar(0.5);
    return [
        c.clone().sub(u).sub(v),
        c.clone().add(u).sub(v),
        c.clone().add(u).add(v),
        c.clone().sub(u).add(v),
    ];
}

function tileMesh(tiles, colours) {
    const positions = new Float32Array(tiles.length * 12);
    const colourData = new Float32Array(tiles.length * 12);
    const indices = [];
    tiles.forEach((corners, t) => {
        corners.forEach((c, k) => {
            positions.set([c.x, c.y, c.z], 12 * t + 3 * k);
            colourData.set(colours[t], 12 * t + 3 * k);
        });
        const b = 4 * t;
        indices.push(b, b + 1, b + 2, b, b + 2, b + 3);
    });
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", new THREE.BufferAttribute(positions, 3));
    geometry.setAttribute("color", new THREE.BufferAttribute(colourData, 3));
    geometry.setIndex(indices);
    return new THREE.Mesh(
        geometry,
        new THREE.MeshBasicMaterial({ vertexColors: true, side: THREE.DoubleSide }),
    );
}

function markerMesh(markers, radius) {
    const mesh = new THREE.InstancedMesh(
        new THREE.OctahedronGeometry(radius),
        new THREE.MeshBasicMaterial(),
        markers.length,
    );
    const matrix = new THREE.Matrix4();
    const colour = new THREE.Color();
    markers.forEach(({ p, colour: [r, g, b] }, i) => {
        mesh.setMatrixAt(i, matrix.makeTranslation(p[0], p[1], p[2]));
        mesh.setColorAt(i, colour.setRGB(r, g, b, THREE.LinearSRGBColorSpace));
    });
    return mesh;
}
