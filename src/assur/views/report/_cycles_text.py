"""The words of the work-cycle report in both languages
(:mod:`assur.views.report.cycles`)."""

from __future__ import annotations

from ...texts import Text, localize
from .labels import check_lang, formatted

__all__ = ["verdict_word"]

_T = {
    "report": Text("Work cycles of the manipulator: combined and separate motion (seed 004)",
                   ru="Рабочие циклы манипулятора: совмещённое и раздельное движение "
                      "(источник 004)"),
    "scenario_combined_equal": Text("combined, V1 = V2 (eq. 60)",
                                    ru="совмещённое, V1 = V2 (ур. 60)"),
    "scenario_combined_ideal": Text("ideal combined, both end together (eq. 61)",
                                    ru="идеальное совмещённое, окончание одновременно "
                                       "(ур. 61)"),
    "scenario_separate_second": Text("separate (a): the stick, then the boom (eq. 62)",
                                     ru="раздельное (а): рукоять, затем стрела (ур. 62)"),
    "scenario_separate_first": Text("separate (b): the boom, then the stick (eq. 62)",
                                    ru="раздельное (б): стрела, затем рукоять (ур. 62)"),
    "T": Text("cycle time T_c", ru="время цикла T_ц"),
    "max_F1": Text("Max force of the boom's cylinder |F1|", ru="Максимальное усилие "
                   "гидроцилиндра подъёма стрелы |F1|"),
    "max_F2": Text("Max force of the stick's cylinder |F2|", ru="Максимальное усилие "
                   "гидроцилиндра привода рукояти |F2|"),
    "fed_F1": Text("Max force of the boom's cylinder in the fed direction σ1·F1",
                   ru="Максимальное усилие гидроцилиндра подъёма стрелы в направлении "
                      "питаемой полости σ1·F1"),
    "fed_F2": Text("Max force of the stick's cylinder in the fed direction σ2·F2",
                   ru="Максимальное усилие гидроцилиндра привода рукояти в направлении "
                      "питаемой полости σ2·F2"),
    "dynamic_F1": Text("Max dynamic part of the boom cylinder's force |F_d1|",
                       ru="Максимальная динамическая составляющая усилия гидроцилиндра "
                          "подъёма стрелы |F_d1|"),
    "dynamic_F2": Text("Max dynamic part of the stick cylinder's force |F_d2|",
                       ru="Максимальная динамическая составляющая усилия гидроцилиндра "
                          "привода рукояти |F_d2|"),
    "static": Text("Max static parts |F_s1| (solid), |F_s2| (dashed)",
                   ru="Максимальные статические составляющие |F_s1| (сплошные), |F_s2| "
                      "(штриховые)"),
    "table": Text("Max cylinder forces over the cycle: {0}",
                  ru="Максимальные усилия гидроцилиндров за цикл: {0}"),
    "ratios": Text("Separate ÷ combined: max |F| against V1 = V2 (eq. 60); in the fed "
                   "direction against ideal combined motion (eq. 61)",
                   ru="Раздельное ÷ совмещённое: max |F| к V1 = V2 (ур. 60); в направлении "
                      "питаемой полости к идеальному совмещению (ур. 61)"),
    "basis_combined_ideal": Text("eq. 61, ideal combined motion, force in the fed direction",
                                 ru="ур. 61, идеальное совмещение, усилие в направлении "
                                    "питаемой полости"),
    "basis_combined_equal": Text("eq. 60, combined motion with V1 = V2, force in the fed "
                                 "direction",
                                 ru="ур. 60, совмещение при V1 = V2, усилие в направлении "
                                    "питаемой полости"),
    "pump_table": Text("At the drive's speeds: through the divider; separate (a), (b)",
                       ru="При скоростях привода: через делитель; раздельно (а), (б)"),
    "drive": Text("Rod speeds of the drive (eqs. 63–68)",
                  ru="Скорости штоков привода (ур. 63–68)"),
    "conclusions": Text("The paper's conclusions against the model",
                        ru="Выводы статьи и модель"),
    "claim": Text("the paper", ru="статья"),
    "model": Text("the model", ru="модель"),
    "verdict": Text("verdict", ru="вывод"),
    "why": Text("why", ru="почему"),
    "agrees": Text("agrees", ru="согласуется"),
    "disagrees": Text("does not agree", ru="не согласуется"),
    "criteria": Text("Basis: the forces in the fed direction (the cylinder's force that the "
                     "chamber fed for the stroke must produce — the piston side extending, the "
                     "rod side retracting; a push against the motion is held by the drained "
                     "side) against ideal combined motion (eq. 61: both rods start and end "
                     "together, the cycle lasts T_c); max |F| and combined motion with V1 = V2 "
                     "(eq. 60: the longer stroke ends later, so its cycle lasts longer than "
                     "T_c) are shown beside. "
                     "Criteria: “about x %” holds within ±{0:.0f} % of x; “3–8 times” when "
                     "every ratio of the dynamic maxima (both cylinders, every T_c) rounds into "
                     "[3, 8]; combined motion is “effective” while separate motion needs at "
                     "least {1:.0f} % more force. The paper does not say in which order its "
                     "separate motion runs: both are computed, and a claim agrees when one "
                     "does. Strokes: {2}.",
                     ru="Основа сравнения: усилия в направлении питаемой полости (усилие "
                        "гидроцилиндра, которое должна создать полость, питаемая для данного "
                        "хода, — поршневая при выдвижении, штоковая при втягивании; усилие "
                        "против движения воспринимает сливная полость) при идеальном "
                        "совмещении (ур. 61: штоки начинают и заканчивают движение "
                        "одновременно, цикл длится T_ц); max |F| и совмещение при V1 = V2 "
                        "(ур. 60: больший ход заканчивается позже, цикл длится дольше T_ц) "
                        "приведены рядом. "
                        "Критерии: «около x %» — в пределах ±{0:.0f} % от x; «в 3–8 раз» — "
                        "если каждое отношение динамических максимумов (оба цилиндра, все "
                        "T_ц) после округления лежит в [3, 8]; совмещение «эффективно», пока "
                        "при раздельном движении усилие больше не менее чем на {1:.0f} %. "
                        "Порядок раздельного движения в статье не указан: рассчитаны оба, "
                        "и вывод согласуется, если согласуется один из них. Ходы: {2}."),
    "slips": Text("The paper's slips and how the model resolves them",
                  ru="Описки статьи и как они разрешены в модели"),
    "figures": Text("Figures", ru="Рисунки"),
    "tables": Text("Tables", ru="Таблицы"),
    "c1_claim": Text("At T_c = {0:g} s separate motion gives a max force of the {1} about "
                     "{2:.0f} % higher than combined motion.",
                     ru="При T_ц = {0:g} с и раздельном движении максимальное усилие {1} "
                        "больше примерно на {2:.0f} %, чем при совмещении движений."),
    "boom": Text("boom's cylinder", ru="гидроцилиндра подъёма стрелы"),
    "stick": Text("stick's cylinder", ru="гидроцилиндра привода рукояти"),
    "c1_model": Text("{0}: {1:+.0f} % with the stick first (a), {2:+.0f} % with the boom "
                     "first (b); max |F|: {3:+.0f} % (a), {4:+.0f} % (b). Against V1 = V2 "
                     "(eq. 60; its cycle at T_c = {5:g} s lasts {6:.1f} s): {7:+.0f} % (a), "
                     "{8:+.0f} % (b) in the fed direction; max |F|: {9:+.0f} % (a), "
                     "{10:+.0f} % (b)",
                     ru="{0}: {1:+.0f} % при движении сначала рукояти (а), {2:+.0f} % — "
                        "сначала стрелы (б); max |F|: {3:+.0f} % (а), {4:+.0f} % (б). При "
                        "V1 = V2 (ур. 60; цикл при T_ц = {5:g} с длится {6:.1f} с): "
                        "{7:+.0f} % (а), {8:+.0f} % (б) в направлении питаемой полости; "
                        "max |F|: {9:+.0f} % (а), {10:+.0f} % (б)"),
    "c1_old_yes": Text("; max |F| against V1 = V2 (eq. 60, whose cycle at T_c = {0:g} s "
                       "lasts {1:.1f} s) would agree",
                       ru="; max |F| при V1 = V2 (ур. 60, цикл при T_ц = {0:g} с длится "
                          "{1:.1f} с) согласовался бы"),
    "c1_old_no": Text("; max |F| against V1 = V2 (eq. 60, whose cycle at T_c = {0:g} s "
                      "lasts {1:.1f} s) would not agree: the push against the motion that it "
                      "compares is held by the drained side",
                      ru="; max |F| при V1 = V2 (ур. 60, цикл при T_ц = {0:g} с длится "
                         "{1:.1f} с) не согласовался бы: сравниваемое им усилие против "
                         "движения воспринимает сливная полость"),
    "c1_yes": Text("order {0} is within ±{1:.0f} % of the paper's {2:.0f} %",
                   ru="порядок {0} в пределах ±{1:.0f} % от {2:.0f} % статьи"),
    "c1_no": Text("neither order comes within ±{0:.0f} % of the paper's {1:.0f} %: the excess "
                  "is the separate motion's dynamic part at V = ΣΔS/T_c, which depends on the "
                  "strokes (the paper's S_max2 and Φ1p0 disagree, see below) and on which "
                  "link moves first; the paper gives neither",
                  ru="ни один порядок не попадает в ±{0:.0f} % от {1:.0f} % статьи: превышение "
                     "— это динамическая составляющая раздельного движения при V = ΣΔS/T_ц, "
                     "она зависит от ходов (S_max2 и Φ1p0 статьи не согласованы, см. ниже) и "
                     "от того, какое звено движется первым; статья не приводит ни того, ни "
                     "другого"),
    "c2_claim": Text("With combined motion the dynamic components fall {0:g}–{1:g} times, "
                     "depending on the cycle time.",
                     ru="При совмещении движений динамические составляющие уменьшаются в "
                        "{0:g}–{1:g} раз в зависимости от времени цикла."),
    "c2_model": Text("against {0}: (a) {1:.1f}–{2:.1f}×, (b) {3:.1f}–{4:.1f}×; against V1 = "
                     "V2 (eq. 60): (a) {5:.1f}–{6:.1f}×, (b) {7:.1f}–{8:.1f}× (max |F_d|, "
                     "boom and stick, every T_c); the ratios vary with T_c by at most {9:.1e}",
                     ru="к режиму «{0}»: (а) {1:.1f}–{2:.1f}×, (б) {3:.1f}–{4:.1f}×; к V1 = V2 "
                        "(ур. 60): (а) {5:.1f}–{6:.1f}×, (б) {7:.1f}–{8:.1f}× (max |F_d|, "
                        "стрела и рукоять, все T_ц); с T_ц отношения меняются не более чем на "
                        "{9:.1e}"),
    "c2_old_yes": Text("; against V1 = V2 (eq. 60) an order would fall within the range",
                       ru="; при V1 = V2 (ур. 60) один из порядков попал бы в диапазон"),
    "c2_old_no": Text("; against V1 = V2 (eq. 60) no order would fall within the range",
                      ru="; при V1 = V2 (ур. 60) ни один порядок не попал бы в диапазон"),
    "c2_yes": Text("order {0} falls within {1:g}–{2:g}×; but the ratio does not depend on T_c: "
                   "at constant rod speeds every dynamic term scales as 1/T_c²",
                   ru="порядок {0} попадает в {1:g}–{2:g}×; но отношение не зависит от T_ц: "
                      "при постоянных скоростях штоков каждая динамическая составляющая "
                      "пропорциональна 1/T_ц²"),
    "c2_no": Text("no order keeps every ratio within {0:g}–{1:g}×; at constant rod speeds "
                  "every dynamic term scales as 1/T_c², so the ratio cannot depend on T_c",
                  ru="ни при одном порядке все отношения не лежат в {0:g}–{1:g}×; при "
                     "постоянных скоростях штоков каждая динамическая составляющая "
                     "пропорциональна 1/T_ц², и отношение не может зависеть от T_ц"),
    "c3_claim": Text("Combined motion is most effective for cycles under {0:g} s.",
                     ru="Совмещение операций особенно эффективно при T_ц < {0:g} с."),
    "c3_model": Text("{0}: separate motion needs ≥ {1:.0f} % more force up to T_c = {2} "
                     "(the gain of combined motion: {3}; at long cycles it tends to the static "
                     "parts' {4:+.0f} %, the paths differ); max |F| against V1 = V2 (eq. 60): "
                     "up to T_c = {5}",
                     ru="{0}: при раздельном движении усилие больше на ≥ {1:.0f} % до "
                        "T_ц = {2} (выигрыш совмещения: {3}; при длинных циклах он стремится к "
                        "{4:+.0f} % статических составляющих — траектории различны); max |F| "
                        "при V1 = V2 (ур. 60): до T_ц = {5}"),
    "c3_never": Text("the gain stays ≥ {0:.0f} % up to the longest cycle, {1:g} s: separate "
                     "motion's static forces in the fed direction are {2:.0f} % higher (its "
                     "paths hold one link while the other moves), which no cycle time removes",
                     ru="выигрыш остаётся ≥ {0:.0f} % до самого длинного цикла, {1:g} с: "
                        "статические усилия в направлении питаемой полости при раздельном "
                        "движении больше на {2:.0f} % (одно звено удерживается, пока "
                        "движется другое), и никакое время цикла этого не устраняет"),
    "gain_at": Text("{0:+.0f} % at {1:g} s", ru="{0:+.0f} % при {1:g} с"),
    "none": Text("no cycle time", ru="ни при каком времени цикла"),
    "c3_yes": Text("the gain falls below {0:.0f} % within 1 s of {1:g} s: the dynamic part "
                   "falls as 1/T_c² while the static part stays",
                   ru="выигрыш падает ниже {0:.0f} % в пределах 1 с от {1:g} с: динамическая "
                      "составляющая падает как 1/T_ц², статическая остаётся"),
    "c3_no": Text("the gain falls below {0:.0f} % at another cycle time than {1:g} s: where "
                  "depends on the ratio of the dynamic to the static part, i.e. on the strokes "
                  "and masses (the paper's strokes are uncertain)",
                  ru="выигрыш падает ниже {0:.0f} % не при {1:g} с: это зависит от отношения "
                     "динамической составляющей к статической, т. е. от ходов и масс (ходы "
                     "статьи неопределённы)"),
    "c4_claim": Text("With the standard pump (Q_h = 80 l/min) and a flow divider the max "
                     "cylinder forces fall {0:.2f}–{1:.2f} times (for the various manipulators).",
                     ru="При установке штатного насоса (Q_h = 80 л/мин) и делителя потока "
                        "максимальные усилия гидроцилиндров снижаются в {0:.2f}–{1:.2f} раза "
                        "(для различных манипуляторов)."),
    "c5_claim": Text("… and the dynamic components of the forces fall {0:g} times.",
                     ru="… а динамические составляющие усилий снижаются в {0:g} раза."),
    "c4_model": Text("separate (the whole flow, V = Q/f) ÷ divider (V = Q/(2f)), force in the "
                     "fed direction: (a) {0:.2f} (boom), {1:.2f} (stick); (b) {2:.2f}, {3:.2f}; "
                     "max |F|: (a) {4:.2f}, {5:.2f}; (b) {6:.2f}, {7:.2f}; the cycle takes "
                     "{8:.2f} s with the divider, {9:.2f} s separate",
                     ru="раздельное (весь поток, V = Q/f) ÷ с делителем (V = Q/(2f)), усилие в "
                        "направлении питаемой полости: (а) {0:.2f} (стрела), {1:.2f} (рукоять); "
                        "(б) {2:.2f}, {3:.2f}; max |F|: (а) {4:.2f}, {5:.2f}; (б) {6:.2f}, "
                        "{7:.2f}; цикл длится {8:.2f} с с делителем, {9:.2f} с раздельно"),
    "c4_old_yes": Text("; max |F| would agree", ru="; по max |F| согласовалось бы"),
    "c4_old_no": Text("; max |F| would not agree", ru="; по max |F| не согласовалось бы"),
    "c5_model": Text("separate (the whole flow, V = Q/f) ÷ divider (V = Q/(2f)), max |F_d|: "
                     "(a) {0:.2f} (boom), {1:.2f} (stick); (b) {2:.2f}, {3:.2f}; the cycle "
                     "takes {4:.2f} s with the divider, {5:.2f} s separate",
                     ru="раздельное (весь поток, V = Q/f) ÷ с делителем (V = Q/(2f)), "
                        "max |F_d|: (а) {0:.2f} (стрела), {1:.2f} (рукоять); (б) {2:.2f}, "
                        "{3:.2f}; цикл длится {4:.2f} с с делителем, {5:.2f} с раздельно"),
    "c4_yes": Text("order {0}: both ratios within {1:g}–{2:g}", ru="порядок {0}: оба отношения "
                   "в пределах {1:g}–{2:g}"),
    "c4_no": Text("no order keeps both ratios within {0:g}–{1:g}: the gain depends on the "
                  "crane's static loads, which the divider does not change",
                  ru="ни при одном порядке оба отношения не лежат в {0:g}–{1:g}: выигрыш "
                     "зависит от статических нагрузок крана, которых делитель не меняет"),
    "c5_yes": Text("order {0}: both ratios within ±{1:.0f} % of {2:g}",
                   ru="порядок {0}: оба отношения в пределах ±{1:.0f} % от {2:g}"),
    "c5_no": Text("no order keeps both ratios within ±{0:.0f} % of {1:g}: with the whole flow "
                  "a rod moves 1/s_j times faster, its dynamic terms (∝ V²) 1/s_j² = 4 times "
                  "larger at the same position, but the maxima fall where the paths differ",
                  ru="ни при одном порядке оба отношения не лежат в пределах ±{0:.0f} % от "
                     "{1:g}: при всём потоке шток движется в 1/s_j раз быстрее, его "
                     "динамические составляющие (∝ V²) в 1/s_j² = 4 раза больше в том же "
                     "положении, но максимумы приходятся на разные положения"),
    "speed_row": Text("{0}: f = {1:.4g} m², rod side {2:.4g} m²",
                      ru="{0}: f = {1:.4g} м², штоковая полость {2:.4g} м²"),
    "combined": Text("combined, divider", ru="совмещённое, делитель"),
    "separate": Text("separate", ru="раздельное"),
    "piston": Text("piston side", ru="поршневая полость"),
    "rod": Text("rod side", ru="штоковая полость"),
}


def verdict_word(agrees, lang="en"):
    """The verdict "agrees" or "does not agree" in ``lang``.

    Examples
    --------
    >>> from assur.views.report.cycles import verdict_word
    >>> verdict_word(True), verdict_word(False), verdict_word(False, "ru")
    ('agrees', 'does not agree', 'не согласуется')
    """
    return localize(_T["agrees" if agrees else "disagrees"], check_lang(lang))


def _t(key, lang, *args):
    s = localize(_T[key], lang)
    return formatted(s, lang, *args) if args else s
