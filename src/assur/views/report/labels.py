"""Russian and English labels and units for tables, figures and the HTML report.

Every text a view prints is looked up here by a key, so that ``lang="ru"`` and
``lang="en"`` give the same report in two languages. Units are written in SI
symbols inside assur (``"m"``, ``"N"``…); :func:`unit` spells them for a
language (``"м"``, ``"Н"`` in Russian).
"""

from __future__ import annotations

import numbers
import re
import string

from ...texts import Text, localize

LANGS = ("en", "ru")

#: key -> {lang: text}
TEXT = {
    # report structure
    "report": {"en": "Analysis report", "ru": "Отчёт о расчёте"},
    "model_file": {"en": "model file", "ru": "файл модели"},
    "inputs_section": {"en": "Inputs", "ru": "Исходные данные"},
    "sim_results": {"en": "Events and energy balance", "ru": "События и баланс энергии"},
    "quantity": {"en": "quantity", "ru": "величина"},
    "motion": {"en": "The mechanism in motion", "ru": "Движение механизма"},
    "drive_section": {"en": "Hydraulic drive", "ru": "Гидропривод"},
    "component": {"en": "component", "ru": "элемент"},
    # the keys of a [[drive]] component: the file's key in English, its meaning in Russian
    "dk_a1": {"en": "a1", "ru": "коэффициент a1 (инерция столба)"},
    "dk_a2": {"en": "a2", "ru": "коэффициент a2 (ламинарные потери)"},
    "dk_a3": {"en": "a3", "ru": "коэффициент a3 (турбулентные потери)"},
    "dk_bore": {"en": "bore", "ru": "диаметр поршня"},
    "dk_bulk_modulus": {"en": "bulk_modulus", "ru": "приведённый модуль упругости"},
    "dk_coordinate": {"en": "coordinate", "ru": "обобщённая координата"},
    "dk_count": {"en": "count", "ru": "число гидроцилиндров"},
    "dk_density": {"en": "density", "ru": "плотность жидкости"},
    "dk_diameter": {"en": "diameter", "ru": "внутренний диаметр"},
    "dk_displacement": {"en": "displacement", "ru": "рабочий объём"},
    "dk_dp_nominal": {"en": "dp_nominal", "ru": "номинальный перепад давления"},
    "dk_eta_volumetric": {"en": "eta_volumetric", "ru": "объёмный КПД"},
    "dk_fittings": {"en": "fittings", "ru": "местные сопротивления ΣK"},
    "dk_length": {"en": "length", "ru": "длина"},
    "dk_nominal_flow": {"en": "nominal_flow", "ru": "номинальный расход"},
    "dk_position": {"en": "position", "ru": "позиция"},
    "dk_regulation_range": {"en": "regulation_range", "ru": "диапазон регулирования"},
    "dk_rod": {"en": "rod", "ru": "диаметр штока"},
    "dk_roughness": {"en": "roughness", "ru": "шероховатость"},
    "dk_s_min": {"en": "s_min", "ru": "длина на упоре (втянут)"},
    "dk_s_max": {"en": "s_max", "ru": "длина на упоре (выдвинут)"},
    "dk_setting": {"en": "setting", "ru": "давление настройки"},
    "dk_share": {"en": "share", "ru": "доля расхода"},
    "dk_shares": {"en": "shares", "ru": "доли расхода"},
    "dk_speed": {"en": "speed", "ru": "частота вращения"},
    "dk_viscosity": {"en": "viscosity", "ru": "кинематическая вязкость"},
    "dk_volume": {"en": "volume", "ru": "объём"},
    "key": {"en": "key", "ru": "ключ"},
    "title": {"en": "title", "ru": "название"},
    "contents": {"en": "Contents", "ru": "Содержание"},
    "verdicts": {"en": "Verdicts", "ru": "Выводы"},
    "status_ok": {"en": "met", "ru": "выполнено"},
    "status_warn": {"en": "near its limit", "ru": "близко к пределу"},
    "status_fail": {"en": "not met", "ru": "не выполнено"},
    "status_info": {"en": "key figure", "ru": "основной показатель"},
    "summary": {"en": "Model", "ru": "Модель"},
    "parameters": {"en": "Parameters", "ru": "Параметры"},
    "groups": {"en": "Structural groups (solved in this order)",
               "ru": "Структурные группы (в порядке решения)"},
    "links": {"en": "Links", "ru": "Звенья"},
    "machine": {"en": "Machine (stability)", "ru": "Машина (устойчивость)"},
    "solved": {"en": "Design conditions solved (Given/Find)",
               "ru": "Решённые условия синтеза (Дано/Найти)"},
    "tables": {"en": "Tables", "ru": "Таблицы"},
    "figures": {"en": "Diagrams", "ru": "Графики"},
    "drawing": {"en": "Drawing of the mechanism", "ru": "Схема механизма"},
    "animation": {"en": "Animation over the range", "ru": "Анимация по диапазону"},
    "warnings": {"en": "Warnings and notes", "ru": "Предупреждения и примечания"},
    "model_notes": {"en": "Seed slips resolved in the model",
                    "ru": "Исправленные ошибки исходного расчёта (модель)"},
    "statics_flags": {"en": "Columns printed with another sign",
                      "ru": "Столбцы, напечатанные с другим знаком"},
    "stability_flags": {"en": "Formulas reproduced as printed",
                        "ru": "Формулы, воспроизведённые как напечатаны"},
    "table_notes": {"en": "Notes to the tables", "ru": "Примечания к таблицам"},
    "no_warnings": {"en": "None.", "ru": "Нет."},
    "name": {"en": "name", "ru": "имя"},
    "value": {"en": "value", "ru": "значение"},
    "unit": {"en": "unit", "ru": "ед."},
    "kind": {"en": "kind", "ru": "тип"},
    "inputs": {"en": "from points", "ru": "исходные точки"},
    "outputs": {"en": "new points", "ru": "новые точки"},
    "points": {"en": "points", "ru": "точки"},
    "variable": {"en": "cylinder (variable length)", "ru": "гидроцилиндр (переменная длина)"},
    "rigid": {"en": "rigid", "ru": "жёсткое"},
    "frame": {"en": "frame", "ru": "стойка"},
    "coordinates": {"en": "Generalized coordinates", "ru": "Обобщённые координаты"},
    "positions": {"en": "positions", "ru": "положений"},
    "table": {"en": "Table", "ru": "Таблица"},
    "inputs_sheet": {"en": "Inputs", "ru": "Исходные данные"},
    "figure": {"en": "Figure", "ru": "Рисунок"},
    "play": {"en": "play / pause", "ru": "пуск / пауза"},
    "position": {"en": "position", "ru": "положение"},
    "generated": {"en": "Generated by assur", "ru": "Создано assur"},
    "yes": {"en": "yes", "ru": "да"},
    "no": {"en": "no", "ru": "нет"},
    "printed_sign": {"en": "printed by the source with the opposite sign",
                  "ru": "в исходном расчёте напечатано с обратным знаком"},
    # table titles
    "t2.1": {"en": "Geometric analysis: link angles", "ru": "Результаты геометрического "
             "анализа (углы наклона звеньев)"},
    "t2.2": {"en": "Geometric analysis: point coordinates",
             "ru": "Результаты геометрического анализа (координаты точек)"},
    "t3.1": {"en": "Kinematic analysis: transfer ratios, transmission numbers, "
                   "angular-velocity analogs",
             "ru": "Результаты кинематического анализа (передаточные отношения, передаточные "
                   "числа, аналоги угловых скоростей)"},
    "t4.1": {"en": "Lift capacity: cylinder force, pressure, capacity, reserve",
             "ru": "Результаты анализа на грузоподъёмность (сила и давление в ГЦ, "
                   "грузоподъёмность, запас)"},
    "t4.1_cylinders": {"en": "Cylinders: force and pressure",
                       "ru": "Гидроцилиндры: сила и давление"},
    "t5.1": {"en": "Force analysis: joint reactions (force of link i on link j)",
             "ru": "Результаты силового анализа (реакция R_ij — сила звена i на звено j)"},
    "t5.2": {"en": "Kinetostatics: joint reactions with the inertia loads (force of link i "
                   "on link j)",
             "ru": "Результаты кинетостатического анализа (реакции с учётом сил инерции, "
                   "R_ij — сила звена i на звено j)"},
    "tD": {"en": "Crank dynamics: reduced moment of inertia, reduced moments, driving moment, "
                 "common centre of mass",
           "ru": "Динамика кривошипного механизма: приведённый момент инерции, приведённые "
                 "моменты, движущий момент, общий центр масс"},
    "c_omega": {"en": "angular velocity of the crank {0}", "ru": "угловая скорость кривошипа {0}"},
    "tV": {"en": "Velocities and accelerations at the crank's speed",
           "ru": "Скорости и ускорения при заданной скорости кривошипа"},
    "c_omega_link": {"en": "angular velocity of link {0}", "ru": "угловая скорость звена {0}"},
    "c_eps_link": {"en": "angular acceleration of link {0}",
                   "ru": "угловое ускорение звена {0}"},
    "c_v_point": {"en": "speed of point {0} (magnitude of its velocity)",
                  "ru": "скорость точки {0} (модуль)"},
    "c_a_point": {"en": "acceleration of point {0} (magnitude)",
                  "ru": "ускорение точки {0} (модуль)"},
    "n_rates": {"en": "at the crank's speed and acceleration of [motion] (table D: ω, ε); "
                      "ω_i = φ_i′·ω, ε_i = φ_i′·ε + φ_i″·ω², v = J·ω, a = J·ε + H·ω²",
                "ru": "при скорости и ускорении кривошипа из [motion] (таблица D: ω, ε); "
                      "ω_i = φ_i′·ω, ε_i = φ_i′·ε + φ_i″·ω², v = J·ω, a = J·ε + H·ω²"},
    "c_eps": {"en": "angular acceleration of the crank {0}",
              "ru": "угловое ускорение кривошипа {0}"},
    "c_Jred": {"en": "reduced moment of inertia J_red", "ru": "приведённый момент инерции J_пр"},
    "c_dJred": {"en": "its derivative dJ_red/dφ", "ru": "его производная dJ_пр/dφ"},
    "c_Mred": {"en": "reduced moment of all loads, inertia included",
               "ru": "приведённый момент всех сил с силами инерции"},
    "c_Mred_loads": {"en": "reduced moment of the applied loads and weights",
                     "ru": "приведённый момент внешних сил и весов"},
    "c_Mred_inertia": {"en": "reduced moment of the inertia loads",
                       "ru": "приведённый момент сил инерции"},
    "c_Md": {"en": "driving moment on the crank", "ru": "движущий момент на кривошипе"},
    "c_T": {"en": "kinetic energy", "ru": "кинетическая энергия"},
    "c_Xc": {"en": "x of the common centre of mass", "ru": "x общего центра масс"},
    "c_Yc": {"en": "y of the common centre of mass", "ru": "y общего центра масс"},
    "c_omega_fw": {"en": "angular velocity of the crank with the flywheel",
                   "ru": "угловая скорость кривошипа с маховиком"},
    "t6.1": {"en": "Stability: axle reactions, shares and limits",
             "ru": "Результаты анализа на устойчивость (реакции осей, доли, пределы)"},
    "tIC": {"en": "Check of the kinematics through the instantaneous centre",
            "ru": "Проверка кинематического анализа через мгновенный полюс вращения"},
    "tF": {"en": "Formulas of the model", "ru": "Формулы модели"},
    # column descriptions
    "c_coord": {"en": "generalized coordinate", "ru": "обобщённая координата"},
    "c_cyl_len": {"en": "cylinder length", "ru": "длина гидроцилиндра"},
    "c_crank": {"en": "crank angle", "ru": "угол кривошипа"},
    "c_slider": {"en": "slider displacement", "ru": "перемещение ползуна"},
    "c_phi": {"en": "angle of link {0}", "ru": "угол звена {0}"},
    "c_phi_dir": {"en": "angle of link {0} ({1} → {2})", "ru": "угол звена {0} ({1} → {2})"},
    "c_x": {"en": "x of point {0}", "ru": "X точки {0}"},
    "c_y": {"en": "y of point {0}", "ru": "Y точки {0}"},
    "c_closure": {"en": "largest closure residual", "ru": "наибольшая невязка замыкания"},
    "closure_check": {"en": "closure of every group ≤ {0} at every position",
                      "ru": "невязка замыкания каждой группы ≤ {0} во всех положениях"},
    "c_U": {"en": "transfer ratio ω{0}/ω{1}", "ru": "передаточное отношение ω{0}/ω{1}"},
    "c_I": {"en": "transmission number dY/d{1} of point {0}",
            "ru": "передаточное число dY/d{1} точки {0}"},
    "c_dphi": {"en": "angular-velocity analog dφ{0}/d{1}",
               "ru": "аналог угловой скорости dφ{0}/d{1}"},
    "c_I_path": {"en": "transmission number dY/d{1} of point {0} along the held path ({2})",
                 "ru": "передаточное число dY/d{1} точки {0} вдоль траектории с "
                       "удержанием ({2})"},
    "c_dphi_path": {"en": "angular-velocity analog dφ{0}/d{1} along the held path ({2})",
                    "ru": "аналог угловой скорости dφ{0}/d{1} вдоль траектории с "
                          "удержанием ({2})"},
    "c_F": {"en": "cylinder force by virtual work ({0})", "ru": "сила на ГЦ ({0})"},
    "c_Frx": {"en": "cylinder force from the reactions ({0})",
              "ru": "сила на ГЦ по реакциям ({0})"},
    "c_p": {"en": "cylinder pressure ({0})", "ru": "давление в ГЦ ({0})"},
    "c_G": {"en": "lift capacity at point {0}", "ru": "грузоподъёмность в точке {0}"},
    "c_dG": {"en": "capacity reserve at {0} against {1} = {2}",
             "ru": "запас грузоподъёмности в точке {0} относительно {1} = {2}"},
    "c_Rx": {"en": "x component of {0}", "ru": "проекция {0} на ось X"},
    "c_Ry": {"en": "y component of {0}", "ru": "проекция {0} на ось Y"},
    "c_R": {"en": "magnitude of {0} (force of {1} on {2})",
            "ru": "модуль {0} (сила звена {1} на звено {2})"},
    "c_Raxle": {"en": "reaction of axle {0}", "ru": "реакция оси {0}"},
    "c_dRaxle": {"en": "share of axle {0}", "ru": "доля нагрузки на ось {0}"},
    "c_Gmax": {"en": "largest implement weight at ≥ {0:g} % on the steered axle",
               "ru": "наибольший вес орудия при ≥ {0:g} % на управляемой оси"},
    "c_Gmax_no_cw": {"en": "the same without counterweights",
                     "ru": "то же без противовесов"},
    "c_steerable": {"en": "steerable (1 = yes)", "ru": "управляемость обеспечена (1 = да)"},
    "c_formula": {"en": "{0} = {1} (a formula of the model)",
                  "ru": "{0} = {1} (формула модели)"},
    "c_Xp": {"en": "x of the instantaneous centre of link {0}",
             "ru": "X мгновенного полюса звена {0}"},
    "c_Yp": {"en": "y of the instantaneous centre of link {0}",
             "ru": "Y мгновенного полюса звена {0}"},
    "c_Iic": {"en": "dφ{1}/d{2}·(X{0} − Xp): I{0} through the instantaneous centre",
              "ru": "dφ{1}/d{2}·(X{0} − Xp): I{0} через мгновенный полюс"},
    # figures
    "f_angles": {"en": "Link angles", "ru": "Углы наклона звеньев"},
    "f_analogs": {"en": "Angular-velocity analogs", "ru": "Аналоги угловых скоростей"},
    "f_transmission": {"en": "Transmission numbers", "ru": "Передаточные числа"},
    "f_capacity": {"en": "Lift capacity", "ru": "Грузоподъёмность"},
    "f_force": {"en": "Cylinder force", "ru": "Сила на ГЦ"},
    "f_pressure": {"en": "Cylinder pressure", "ru": "Давление в ГЦ"},
    "f_reactions": {"en": "Joint reactions", "ru": "Реакции в кинематических парах"},
    "f_hodograph": {"en": "Hodograph of reaction {0}", "ru": "Годограф реакции {0}"},
    "f_stability": {"en": "Load on the steered axle", "ru": "Нагрузка на управляемые колёса"},
    "y_angle": {"en": "angle φ", "ru": "угол φ"},
    "y_analog": {"en": "analog dφ/d{0}", "ru": "аналог dφ/d{0}"},
    "y_transmission": {"en": "transmission number I", "ru": "передаточное число I"},
    "y_capacity": {"en": "capacity G", "ru": "грузоподъёмность G"},
    "y_force": {"en": "force F", "ru": "сила F"},
    "y_pressure": {"en": "pressure p", "ru": "давление p"},
    "y_reaction": {"en": "reaction |R|", "ru": "реакция |R|"},
    "y_share": {"en": "share of the total weight", "ru": "доля от общего веса"},
    "load": {"en": "load {0} = {1}", "ru": "нагрузка {0} = {1}"},
    "force_max": {"en": "available Fₘₐₓ = {0}",
                  "ru": "максимальная Fₘₐₓ = {0}"},
    "p_max": {"en": "pₘₐₓ = {0}", "ru": "pₘₐₓ = {0}"},
    "min_share": {"en": "limit {0:g} %", "ru": "предел {0:g} %"},
    "steered_axle": {"en": "steered axle {0}", "ru": "управляемая ось {0}"},
    "other_axle": {"en": "axle {0}", "ru": "ось {0}"},
    "start": {"en": "start", "ru": "начало"},
    "end": {"en": "end", "ru": "конец"},
    "x_m": {"en": "x", "ru": "X"},
    "y_m": {"en": "y", "ru": "Y"},
    "at": {"en": "{0} = {1}", "ru": "{0} = {1}"},
    "centre_of_mass": {"en": "centre of mass", "ru": "центр масс"},
    "dynamics": {"en": "Crank dynamics (inertia, flywheel, balancing)",
                 "ru": "Динамика (силы инерции, маховик, уравновешивание)"},
    "dyn_speed": {"en": "crank {0}: mean |ω| = {1}",
                  "ru": "кривошип {0}: среднее |ω| = {1}"},
    "dyn_jred": {"en": "reduced moment of inertia J_red = {0} … {1}",
                 "ru": "приведённый момент инерции J_пр = {0} … {1}"},
    "dyn_md": {"en": "driving moment M_d = {0} … {1} (table D)",
               "ru": "движущий момент M_д = {0} … {1} (таблица D)"},
    "dyn_centre": {"en": "common centre of mass of {3}: A_x = {0}, A_y = {1}, enclosed area {2}",
                   "ru": "общий центр масс {3}: A_x = {0}, A_y = {1}, площадь траектории {2}"},
    "dyn_flywheel": {"en": "flywheel (energy–mass method): δ = {0}, J_f = {1} (ω = {2} … {3}, "
                           "constant M_d = {4}; the approximations ΔE_max/(δω²) = {5}, "
                           "Mertsalov {6})",
                     "ru": "маховик (метод энергомасс): δ = {0}, J_м = {1} (ω = {2} … {3}, "
                           "постоянный M_д = {4}; приближения ΔE_max/(δω²) = {5}, по Мерцалову "
                           "{6})"},
    "dyn_mass": {"en": "{1} on link {0} at {2} along, {3} offset",
                 "ru": "{1} на звене {0}: {2} вдоль, {3} в сторону"},
    "dyn_balance": {"en": "balancing ({0}): {1}; then A_x = {2}, A_y = {3}, area {4}",
                    "ru": "уравновешивание ({0}): {1}; после него A_x = {2}, A_y = {3}, "
                          "площадь {4}"},
    "c_dist": {"en": "distance {0} = |{1}–{2}|", "ru": "расстояние {0} = |{1}–{2}|"},
    "c_ddist": {"en": "analog d{0}/d{1} of the distance {0}",
                "ru": "аналог d{0}/d{1} расстояния {0}"},
    "c_ddphi": {"en": "angular-acceleration analog d²φ{0}/d{1}²",
                "ru": "аналог углового ускорения d²φ{0}/d{1}²"},
    "c_dddist": {"en": "second analog d²{0}/d{1}² of the distance {0}",
                 "ru": "второй аналог d²{0}/d{1}² расстояния {0}"},
    "c_dU": {"en": "derivative dU{0}{1}/d{2} of the transfer ratio",
             "ru": "производная dU{0}{1}/d{2} передаточного отношения"},
    "c_Lspring": {"en": "length of the spring {0}", "ru": "длина пружины {0}"},
    "c_Tspring": {"en": "tension of one spring {0}", "ru": "сила растяжения одной пружины {0}"},
    "c_Fspring": {"en": "force of all the springs {0} (count × tension)",
                  "ru": "сила всех пружин {0} (количество × растяжение)"},
    "wrapped": {"en": "angles wrapped to [{0}, {1}) as the seeds print them",
                "ru": "углы приведены к [{0}; {1}), как в исходных расчётах"},
    "rotation": {"en": "analogs along the direction of rotation of {0} ({1}): dφ/d{0} · "
                       "sign {0}' with {0}' = {2:+d}, as the seeds write them",
                 "ru": "аналоги по направлению вращения {0} ({1}): dφ/d{0} · sign {0}', "
                       "{0}' = {2:+d}, как в исходных расчётах"},
    "cw": {"en": "clockwise", "ru": "по часовой стрелке"},
    "ccw": {"en": "counter-clockwise", "ru": "против часовой стрелки"},
    "objective_amplitudes": {"en": "the sum of the amplitudes A_x + A_y",
                             "ru": "сумма амплитуд A_x + A_y"},
    "objective_max_amplitude": {"en": "the larger amplitude", "ru": "наибольшая амплитуда"},
    "objective_area": {"en": "the area of the path", "ru": "площадь траектории"},
    # figures of the crank dynamics (report.dynamics)
    "dyn_f_com": {"en": "Common centre of mass over a crank turn",
              "ru": "Перемещение общего центра масс за оборот кривошипа"},
    "dyn_before": {"en": "without counter-masses", "ru": "без противовесов"},
    "dyn_after": {"en": "with counter-masses", "ru": "с противовесами"},
    "dyn_amp": {"en": "A_x = {0}, A_y = {1}, area {2}",
            "ru": "A_x = {0}, A_y = {1}, площадь {2}"},
    "dyn_mean": {"en": "about its mean (x̄, ȳ) = ({0}, {1}) {2}",
             "ru": "относительно среднего (x̄, ȳ) = ({0}, {1}) {2}"},
    "dyn_f_hodo": {"en": "Reaction hodographs over a turn, inertia loads included",
                   "ru": "Годографы реакций за оборот с силами инерции"},
    "without_inertia": {"en": " (without inertia loads)", "ru": " (без сил инерции)"},
    "dyn_f_mred": {"en": "Reduced moment on the crank", "ru": "Приведённый момент на кривошипе"},
    "dyn_m_all": {"en": "all loads, inertia included", "ru": "все нагрузки с силами инерции"},
    "dyn_m_static": {"en": "without inertia", "ru": "без сил инерции"},
    "dyn_m_drive": {"en": "driving moment (from the reactions)",
                "ru": "движущий момент (по реакциям)"},
    "dyn_f_jred": {"en": "Reduced moment of inertia", "ru": "Приведённый момент инерции"},
    "dyn_f_wit": {"en": "Energy–mass diagram and the flywheel",
              "ru": "Диаграмма энергомасс и маховик"},
    "dyn_wit_tan": {"en": "tangents of ω_max, ω_min", "ru": "касательные ω_max, ω_min"},
    "dyn_fw": {"en": "they meet at (−J_f, −T0): J_f = {0}, δ = {1}",
           "ru": "пересекаются в (−J_м, −T0): J_м = {0}, δ = {1}"},
    "dyn_omega": {"en": "crank speed |ω|", "ru": "угловая скорость кривошипа |ω|"},
    "dyn_angle": {"en": "crank angle {0}", "ru": "угол кривошипа {0}"},
    "dyn_energy": {"en": "work of the loads ΔE", "ru": "работа сил ΔE"},
    "dyn_force_x": {"en": "R_x", "ru": "R_x"},
    "dyn_force_y": {"en": "R_y", "ru": "R_y"},
    "tL": {"en": "Standard lift test (ISO 789-2 / SAE J283): force available over the lift range",
           "ru": "Стандартное испытание грузоподъёмности (ISO 789-2 / SAE J283): усилие по "
                 "диапазону подъёма"},
    "c_Gtest": {"en": "vertical force available at the hitch point {0}",
                "ru": "вертикальное усилие, развиваемое в точке навески {0}"},
    "c_Gtest_frame": {"en": "vertical force available at the test frame's point {0}",
                      "ru": "вертикальное усилие на раме испытаний в точке {0}"},
    "lift_test_note": {"en": "at {0} of the relief pressure: {1}, cylinder force {2}; {3} heights "
                             "of the hitch point evenly spaced over the lift range; the "
                             "implement's weight is not part of the test",
                       "ru": "при {0} давления настройки предохранительного клапана: {1}, "
                             "усилие гидроцилиндров {2}; {3} высот точки навески равномерно по "
                             "диапазону подъёма; вес орудия в испытание не входит"},
    "lift_test_min": {"en": "minimum over the lift range at the hitch point {0}: {1}",
                      "ru": "минимум по диапазону подъёма в точке навески {0}: {1}"},
    "lift_test_min_frame": {"en": "minimum over the lift range on the frame ({0}): {1}",
                            "ru": "минимум по диапазону подъёма на раме ({0}): {1}"},
    # simulation in time of a hydraulic drive (report/simulation.py; lab 6 figs. 6.3–6.7)
    "sim_report": {"en": "Simulation of the hydraulic drive", "ru": "Моделирование гидропривода"},
    "sim_motion": {"en": "The mechanism in motion (real time)",
                   "ru": "Механизм в движении (в реальном времени)"},
    "sim_time": {"en": "time t", "ru": "время t"},
    "sim_p": {"en": "Pressure at the pump p1 and at the cylinder p2",
              "ru": "Давление у насоса p1 и у гидроцилиндра p2"},
    "sim_dp": {"en": "Rate of the pressure at the pump dp1/dt",
               "ru": "Скорость изменения давления у насоса dp1/dt"},
    "sim_s": {"en": "Generalized coordinate {0}", "ru": "Обобщённая координата {0}"},
    "sim_v": {"en": "Speed of the generalized coordinate d{0}/dt",
              "ru": "Скорость обобщённой координаты d{0}/dt"},
    "sim_a": {"en": "Acceleration of the generalized coordinate d²{0}/dt²",
              "ru": "Ускорение обобщённой координаты d²{0}/dt²"},
    "sim_m": {"en": "Reduced mass m({0}) and its derivative m'({0})",
              "ru": "Приведённая масса m({0}) и её производная m'({0})"},
    "sim_steady": {"en": "Q/A (steady speed)", "ru": "Q/A (установившаяся скорость)"},
    "sim_status": {"en": "status: {0}", "ru": "результат: {0}"},
    "sim_reached": {"en": "reached t_end", "ru": "расчёт доведён до t_end"},
    "sim_events": {"en": "Events", "ru": "События"},
    "sim_energy": {"en": "Energy balance", "ru": "Энергетический баланс"},
    "sim_ev_lift-off": {"en": "lift-off from the stop", "ru": "отрыв от упора"},
    "sim_ev_end of stroke": {"en": "end of stroke", "ru": "конец хода"},
    "sim_ev_relief opens": {"en": "relief valve opens",
                            "ru": "открытие предохранительного клапана"},
    "sim_en_pump": {"en": "work of the pump", "ru": "работа насоса"},
    "sim_en_relief": {"en": "lost in the relief valve", "ru": "потери в предохранительном клапане"},
    "sim_en_line": {"en": "lost in the lines and the valve",
                    "ru": "потери в магистрали и распределителе"},
    "sim_en_impact": {"en": "lost at the stops", "ru": "потери на упорах"},
    "sim_en_mechanism_kinetic": {"en": "kinetic energy of the mechanism",
                                 "ru": "кинетическая энергия механизма"},
    "sim_en_line_kinetic": {"en": "kinetic energy of the oil column",
                            "ru": "кинетическая энергия столба жидкости"},
    "sim_en_loads": {"en": "work against the loads", "ru": "работа против нагрузок"},
    "sim_en_oil": {"en": "work of compressing the oil", "ru": "работа сжатия жидкости"},
    "sim_en_residual": {"en": "residual of the balance", "ru": "невязка баланса"},
    "sim_steady_line": {"en": "steady rod speed Q/A = {0} {2}; {1} evaluations of "
                              "the right-hand side",
                        "ru": "установившаяся скорость штока Q/A = {0} {2}; "
                              "{1} вычислений правой части"},
    "renamed": {"en": "{0} is also a coordinate's name: this column is {1}",
                "ru": "{0} — также имя обобщённой координаты: этот столбец назван {1}"},
    "solved_line": {"en": "{0} = {1}: {2} ({3}residual {4})",
                    "ru": "{0} = {1}: {2} ({3}невязка {4})"},
    "singular": {"en": "{0} is singular at {1} position(s) ({2}); shown as empty there",
                 "ru": "{0} не определено в {1} положениях ({2}); там оставлено пустым"},
    # several coordinates (the loader of seed 001 lab 1): quantities along a coordinate
    # that does not move a point or turn a link are left out, with these notes
    "absent": {"en": "{0} does not move {1}; not shown along {0} (identically zero or 0/0): "
                     "{2}",
               "ru": "{0} не перемещает {1}; по {0} не приводятся (тождественно нуль или "
                     "0/0): {2}"},
    "absent_points": {"en": "points", "ru": "точки"},
    "absent_links": {"en": "links", "ru": "звенья"},
    "absent_analogs": {"en": "their analogs, ratios and transmission numbers",
                       "ru": "их аналоги, передаточные отношения и числа"},
    "absent_capacity": {"en": "the capacity of cylinder {0}", "ru": "грузоподъёмность "
                                                                    "гидроцилиндра {0}"},
    "g_min": {"en": "{0}: minimum {1} at {2}", "ru": "{0}: минимум {1} при {2}"},
    "g_reach": {"en": "{0} at the farthest reach of {1} (X{1} = {2}, seed 001 lab 1 "
                      "eq. 14a): {3} at {4}",
                "ru": "{0} при наибольшем вылете точки {1} (X{1} = {2}, источник 001, "
                      "лаб. 1, формула 14а): {3} при {4}"},
    "g_dead": {"en": "the capacities carry the dead loads of the links {0} (seed 001 lab 1 "
                     "eq. 14)",
               "ru": "грузоподъёмность учитывает постоянные нагрузки звеньев {0} (источник "
                     "001, лаб. 1, формула 14)"},
    "derived_links": {"en": "the model file has no [links]: each link's angle is the "
                            "direction from its first point to its second as the groups "
                            "define them (written with the angle); the analogs dφ do not "
                            "depend on which two points of a link are taken, the angle only "
                            "by a constant",
                      "ru": "в файле модели нет раздела [links]: угол каждого звена — "
                            "направление от его первой точки ко второй в порядке задания "
                            "группами (указано при угле); аналоги dφ не зависят от выбора "
                            "двух точек звена, угол — лишь на постоянную"},
    "paired": {"en": "the coordinates move together, position by position", "ru":
               "обобщённые координаты изменяются совместно, положение за положением"},
    "tG": {"en": "Lift capacity maps G({0}, {1}) (seed 001 lab 1 eq. 14)",
           "ru": "Карты грузоподъёмности G({0}, {1}) (источник 001, лаб. 1, формула 14)"},
    "g_map": {"en": "rows: {0}; a column per capacity and value of {1} (G<p>_<c>@{1}=<value>: "
                    "the capacity of the cylinder on c at point p); the same numbers as table "
                    "4.1, arranged as the map",
              "ru": "строки: {0}; столбец на каждую грузоподъёмность и значение {1} "
                    "(G<p>_<c>@{1}=<значение>: грузоподъёмность гидроцилиндра по c в точке p); "
                    "те же числа, что в таблице 4.1, в виде карты"},
    "paired_axis": {"en": "{0} moves with it", "ru": "{0} изменяется вместе с ней"},
    "f_map": {"en": "{0}: map over {1} and {2}", "ru": "{0}: карта по {1} и {2}"},
    "gmax_min": {"en": "{0}: minimum {1} ({2} at g = {3}) at {4}",
                 "ru": "{0}: минимум {1} ({2} при g = {3}) при {4}"},
}

#: SI unit symbols -> Russian spelling
UNITS_RU = {"m": "м", "deg": "°", "-": "-", "N": "Н", "Pa": "Па", "%": "%",
            "rad/m": "рад/м", "rad": "рад", "kN": "кН", "MPa": "МПа", "N·m": "Н·м",
            "kg": "кг", "kg·m²": "кг·м²", "N/m": "Н/м", "m/rad": "м/рад", "m/m": "м/м",
            "rad/rad": "рад/рад", "rad/s": "рад/с", "rad/s²": "рад/с²", "J": "Дж",
            "kg·m²/rad": "кг·м²/рад", "s": "с", "m/s": "м/с", "m/s²": "м/с²",
            "MPa/s": "МПа/с", "kg/m": "кг/м"}


def check_lang(lang: str) -> str:
    """Return ``lang`` or raise ValueError listing the valid ones."""
    if lang not in LANGS:
        raise ValueError(f"lang must be one of: {list(LANGS)}; got {lang!r}")
    return lang


class _Numbers(string.Formatter):
    """``str.format`` whose numbers take the decimal comma in Russian."""

    def __init__(self, lang):
        super().__init__()
        self.lang = lang

    def format_field(self, value, format_spec):
        text = super().format_field(value, format_spec)
        if self.lang == "ru" and isinstance(value, numbers.Real) and not isinstance(value, bool):
            text = text.replace(".", ",")
        return text


def formatted(text: str, lang: str, *args) -> str:
    """``text.format(*args)`` with every number in ``lang``'s notation (the decimal
    comma in Russian) and a :class:`assur.texts.Text` argument in ``lang``.

    Examples
    --------
    >>> from assur.views.report.labels import formatted
    >>> formatted("{0:.2f} × {1}", "ru", 1.5, "S1"), formatted("{0:g} s", "en", 0.25)
    ('1,50 × S1', '0.25 s')
    """
    return _Numbers(lang).format(text, *(localize(a, lang) if isinstance(a, Text) else a
                                         for a in args))


def t(key: str, lang: str, *args) -> str:
    """The text ``key`` in ``lang``, formatted with ``args`` (a model's name or text
    given in several languages, :class:`assur.texts.Text`, in ``lang``'s; numbers with
    the decimal comma in Russian, :func:`formatted`)."""
    s = TEXT[key][check_lang(lang)]
    return formatted(s, lang, *args) if args else s


#: unit atoms (a symbol with its prefix) -> Russian spelling, for units a user wrote
_ATOMS_RU = {"m": "м", "mm": "мм", "cm": "см", "dm": "дм", "km": "км", "N": "Н", "kN": "кН",
             "MN": "МН", "Pa": "Па", "kPa": "кПа", "MPa": "МПа", "GPa": "ГПа", "bar": "бар",
             "kg": "кг", "g": "г", "t": "т", "s": "с", "min": "мин", "h": "ч", "rad": "рад",
             "deg": "град", "rpm": "об/мин", "l": "л", "L": "л", "W": "Вт", "kW": "кВт",
             "J": "Дж", "kJ": "кДж", "kgf": "кгс", "tf": "тс", "Hz": "Гц", "percent": "%",
             "in": "дюйм", "inch": "дюйм", "ft": "фут", "lbf": "фунт-сила", "lb": "фунт",
             "psi": "фунт/дюйм²", "gal": "галлон", "hp": "л. с.", "mrad": "мрад"}


#: characters with a subscript form in Unicode (and in DejaVu Sans, the figures' font)
_SUBSCRIPT = str.maketrans("0123456789+-=()aehijklmnoprstuvx",
                           "₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ")


def symbol(base: str, sub="", prime: bool = False) -> str:
    """A symbol with its index as a figure writes it, in plain Unicode text: ``φ₃₄``,
    ``pₘₐₓ``. An index with a character that has no subscript form (``S6``, ``w3``,
    ``red``: and letters in small subscripts are hard to read, ``S6`` looks like ``56``)
    follows the symbol after a space. No TeX: matplotlib's mathtext parser cost a
    report about a second, and a name with ``_`` or ``$`` is printed as the model names it.

    Examples
    --------
    >>> from assur.views.report.labels import symbol
    >>> symbol("φ", "34"), symbol("φ", "3", prime=True), symbol("p", "max")
    ('φ₃₄', 'φ′₃', 'pₘₐₓ')
    >>> symbol("φ", "w3"), symbol("J", "red"), symbol("F", "S_1"), symbol("R")
    ('φ w3', 'J red', 'F S_1', 'R')
    """
    sub = str(sub)
    head = base + ("′" if prime else "")
    if not sub:
        return head
    low = sub.translate(_SUBSCRIPT)
    if (sub.isdigit() or sub.isalpha()) and all(ord(c) > 127 for c in low):
        return head + low
    return head + " " + sub


def unit(u: str, lang: str) -> str:
    """A unit symbol spelled for ``lang`` (as written in English; in Russian each
    symbol with its prefix translated: ``kN·m`` → ``кН·м``, ``l/min`` → ``л/мин``)."""
    if check_lang(lang) != "ru":
        return u
    if u in UNITS_RU:
        return UNITS_RU[u]
    return re.sub(r"[A-Za-z]+", lambda m: _ATOMS_RU.get(m.group(0), m.group(0)), u)
